#include <deal.II/base/geometry_info.h>

#include <xcrack/contact/multiplier_space.h>
#include <xcrack/input_error.h>
#include <xcrack/xfem/enrichment.h>

#include <algorithm>
#include <limits>
#include <set>
#include <tuple>

namespace xcrack
{
  namespace Contact
  {
    namespace
    {
      /// A strict order of points, the same on every rank.
      template <int dim>
      bool
      before(const Point<dim> &a, const Point<dim> &b)
      {
        for (unsigned int d = 0; d < dim; ++d)
          if (a[d] != b[d])
            return a[d] < b[d];
        return false;
      }

      template <int dim>
      struct Before
      {
        bool
        operator()(const Point<dim> &a, const Point<dim> &b) const
        {
          return before(a, b);
        }
      };

      /**
       * Where the lips of a cell cross its edges: an edge whose ends' lsn
       * have opposite signs, crossed at lst < 0 (behind the front), or a
       * vertex on the lips (lsn = 0 there: a crack fitted to it). A crossing
       * of edge (a, b) belongs to the nearer of a and b (the one that sorts
       * first on a tie); a vertex crossing to the vertex.
       */
      struct Crossing
      {
        /// The edge's ends (b = a for a vertex crossing).
        unsigned int a, b;
        /// The vertex whose enriched DoF controls the jump there.
        unsigned int vertex;
      };

      template <int dim>
      std::vector<Crossing>
      crossings(const typename DoFHandler<dim>::active_cell_iterator &cell,
                const std::vector<double>                            &lsn,
                const std::vector<double>                            &lst)
      {
        std::vector<Crossing>  found;
        std::set<unsigned int> on_lips;
        for (unsigned int line = 0; line < GeometryInfo<dim>::lines_per_cell;
             ++line)
          {
            const unsigned int a =
              GeometryInfo<dim>::line_to_cell_vertices(line, 0);
            const unsigned int b =
              GeometryInfo<dim>::line_to_cell_vertices(line, 1);
            for (const unsigned int v : {a, b})
              if (lsn[v] == 0 && lst[v] < 0 && on_lips.insert(v).second)
                found.push_back({v, v, v});
            if (lsn[a] * lsn[b] >= 0)
              continue;
            const double t = lsn[a] / (lsn[a] - lsn[b]);
            if ((1 - t) * lst[a] + t * lst[b] >= 0)
              continue; // the crossing lies ahead of the front
            const unsigned int nearer =
              (t < 0.5                                  ? a :
               t > 0.5                                  ? b :
               before(cell->vertex(a), cell->vertex(b)) ? a :
                                                          b);
            found.push_back({a, b, nearer});
          }
        return found;
      }

      /// The crossing's function at @p x (reference coordinates): N_a + N_b
      /// (one on the edge, zero on the faces without a or b), N_a for a
      /// vertex.
      template <int dim>
      double
      crossing_function(const Crossing &crossing, const Point<dim> &x)
      {
        double w = GeometryInfo<dim>::d_linear_shape_function(x, crossing.a);
        if (crossing.b != crossing.a)
          w += GeometryInfo<dim>::d_linear_shape_function(x, crossing.b);
        return w;
      }
    } // namespace



    template <int dim>
    std::string
    MultiplierSpace<dim>::names()
    {
      return "vital nodes|edges|cells";
    }



    template <int dim>
    typename MultiplierSpace<dim>::Type
    MultiplierSpace<dim>::parse(const std::string &name)
    {
      if (name == "edges")
        return Type::edges;
      if (name == "cells")
        return Type::cells;
      check_input(name == "vital nodes",
                  "Multiplier space = " + name + ": not one of " + names());
      return Type::vital_nodes;
    }



    template <int dim>
    MultiplierSpace<dim>::MultiplierSpace(const Type type)
      : type_(type)
    {}



    template <int dim>
    typename MultiplierSpace<dim>::Type
    MultiplierSpace<dim>::type() const
    {
      return type_;
    }



    template <int dim>
    void
    MultiplierSpace<dim>::reinit(const DoFHandler<dim> &dof_handler,
                                 const Enrichment<dim> &enrichment,
                                 const MPI_Comm         comm)
    {
      bases.clear();
      locations.clear();
      // Per owned cell with lips: the keys of its multipliers, its
      // crossings and its lip points.
      struct Pending
      {
        CellId                  id;
        std::vector<Point<dim>> keys;
        /// The crossings, and the key (index into keys) each belongs to.
        std::vector<Crossing>     crossings;
        std::vector<unsigned int> key_of;
        std::vector<Point<dim>>   points;
      };
      std::vector<Pending> pending;
      std::vector<double>  my_keys;
      for (const auto &cell : dof_handler.active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          const auto rule = enrichment.lip_quadrature(cell);
          if (rule.size() == 0)
            continue;
          Pending p{cell->id(), {}, {}, {}, rule.get_points()};
          if (type_ == Type::cells)
            p.keys.push_back(cell->center());
          else
            {
              const auto [lsn, lst] = enrichment.level_set_values(cell);
              p.crossings           = crossings<dim>(cell, lsn, lst);
              if (p.crossings.empty())
                {
                  // Lips that cross no edge (a piece ending inside the
                  // cell): the vertex nearest to them.
                  Point<dim> centre;
                  for (const Point<dim> &x : p.points)
                    centre += x / static_cast<double>(p.points.size());
                  unsigned int nearest = 0;
                  for (const unsigned int v : cell->vertex_indices())
                    if (centre.distance(
                          GeometryInfo<dim>::unit_cell_vertex(v)) <
                        centre.distance(
                          GeometryInfo<dim>::unit_cell_vertex(nearest)))
                      nearest = v;
                  p.crossings.push_back({nearest, nearest, nearest});
                }
              for (const Crossing &c : p.crossings)
                {
                  // Vital nodes: the crossings of a vertex share its key;
                  // edges: each crossing has its own (the edge's middle).
                  const Point<dim> key =
                    (type_ == Type::vital_nodes ?
                       cell->vertex(c.vertex) :
                       Point<dim>(0.5 *
                                  (cell->vertex(c.a) + cell->vertex(c.b))));
                  unsigned int k = 0;
                  while (k < p.keys.size() && p.keys[k] != key)
                    ++k;
                  if (k == p.keys.size())
                    p.keys.push_back(key);
                  p.key_of.push_back(k);
                }
            }
          for (const Point<dim> &key : p.keys)
            for (unsigned int d = 0; d < dim; ++d)
              my_keys.push_back(key[d]);
          pending.push_back(std::move(p));
        }

      // Every rank's keys: the owner of a key is the lowest rank that has
      // it; numbered by owner, then by the key's order.
      const std::vector<std::vector<double>> all =
        Utilities::MPI::all_gather(comm, my_keys);
      std::map<Point<dim>, unsigned int, Before<dim>> owner;
      for (unsigned int rank = 0; rank < all.size(); ++rank)
        for (std::size_t i = 0; i < all[rank].size(); i += dim)
          {
            Point<dim> key;
            for (unsigned int d = 0; d < dim; ++d)
              key[d] = all[rank][i + d];
            owner.emplace(key, rank);
          }
      std::vector<std::pair<unsigned int, Point<dim>>> order;
      for (const auto &[key, rank] : owner)
        order.emplace_back(rank, key);
      std::stable_sort(order.begin(),
                       order.end(),
                       [](const auto &a, const auto &b) {
                         return a.first < b.first;
                       });
      const unsigned int me = Utilities::MPI::this_mpi_process(comm);
      std::map<Point<dim>, unsigned int, Before<dim>> index;
      owned = {0, 0};
      for (unsigned int k = 0; k < order.size(); ++k)
        {
          index[order[k].second] = k;
          locations.push_back(order[k].second);
          if (order[k].first < me)
            owned.first = owned.second = k + 1;
          else if (order[k].first == me)
            owned.second = k + 1;
        }

      for (const Pending &p : pending)
        {
          CellBasis &basis = bases[p.id];
          for (const Point<dim> &key : p.keys)
            basis.multipliers.push_back(index.at(key));
          const unsigned int n = basis.multipliers.size();
          basis.values.assign(p.points.size(), std::vector<double>(n, 1.));
          if (type_ == Type::cells)
            continue;
          // psi_k = (sum of the functions of k's crossings) / (sum of all):
          // the cell's functions sum to one.
          for (unsigned int q = 0; q < p.points.size(); ++q)
            {
              std::fill(basis.values[q].begin(), basis.values[q].end(), 0.);
              double sum = 0;
              for (unsigned int c = 0; c < p.crossings.size(); ++c)
                {
                  const double w =
                    crossing_function(p.crossings[c], p.points[q]);
                  basis.values[q][p.key_of[c]] += w;
                  sum += w;
                }
              // Positive on the lips: inside the cell every function is, and
              // the lips reach a face only through edges of that face.
              for (unsigned int j = 0; j < n; ++j)
                basis.values[q][j] =
                  (sum > 0 ? basis.values[q][j] / sum : 1. / n);
            }
        }
    }



    template <int dim>
    unsigned int
    MultiplierSpace<dim>::size() const
    {
      return locations.size();
    }



    template <int dim>
    std::pair<unsigned int, unsigned int>
    MultiplierSpace<dim>::owned_range() const
    {
      return owned;
    }



    template <int dim>
    const Point<dim> &
    MultiplierSpace<dim>::location(const unsigned int k) const
    {
      return locations[k];
    }



    template <int dim>
    const typename MultiplierSpace<dim>::CellBasis *
    MultiplierSpace<dim>::basis(const CellId &cell) const
    {
      const auto it = bases.find(cell);
      return (it == bases.end() ? nullptr : &it->second);
    }



    template class MultiplierSpace<2>;
    template class MultiplierSpace<3>;
  } // namespace Contact
} // namespace xcrack
