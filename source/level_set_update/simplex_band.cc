#include <deal.II/base/mpi.h>

#include <xcrack/level_set_update/simplex_band.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    namespace
    {
      /// The Kuhn split of the reference cell: the simplices along the
      /// paths from vertex 0 to the opposite vertex, one per order of the
      /// directions (deal.II numbers vertex v by its coordinates' bits).
      template <int dim>
      std::vector<std::array<unsigned int, dim + 1>>
      kuhn_simplices()
      {
        std::array<unsigned int, dim> order;
        std::iota(order.begin(), order.end(), 0u);
        std::vector<std::array<unsigned int, dim + 1>> result;
        do
          {
            std::array<unsigned int, dim + 1> simplex;
            simplex[0] = 0;
            for (unsigned int k = 0; k < dim; ++k)
              simplex[k + 1] = simplex[k] | (1u << order[k]);
            result.push_back(simplex);
        } while (std::next_permutation(order.begin(), order.end()));
        return result;
      }
    } // namespace



    template <int dim>
    SimplexBand<dim>::SimplexBand(std::vector<Cell> cells)
    {
      const auto centre = [](const Cell &c) {
        std::array<double, dim> x{};
        for (const Point<dim> &v : c.vertices)
          for (unsigned int d = 0; d < dim; ++d)
            x[d] += v[d];
        return x;
      };
      std::sort(cells.begin(), cells.end(), [&](const Cell &a, const Cell &b) {
        return centre(a) < centre(b);
      });

      // Vertices closer than a millionth of the smallest edge are one: the
      // ranks compute a vertex shared by their cells each on its own, and
      // on a curved manifold the results may differ in the last bits.
      double shortest = std::numeric_limits<double>::max();
      for (const Cell &cell : cells)
        for (unsigned int d = 0; d < dim; ++d)
          shortest =
            std::min(shortest,
                     cell.vertices[0].distance(cell.vertices[1u << d]));
      tolerance = 1e-6 * shortest;

      const auto split = kuhn_simplices<dim>();
      for (const Cell &cell : cells)
        {
          std::array<unsigned int, n_corners> node;
          for (unsigned int v = 0; v < n_corners; ++v)
            {
              std::size_t i = find(cell.vertices[v]);
              if (i == none)
                {
                  i = points.size();
                  index.emplace(bin(cell.vertices[v]), i);
                  points.push_back(cell.vertices[v]);
                  node_lsn.push_back(cell.lsn[v]);
                  node_lst.push_back(cell.lst[v]);
                }
              node[v] = i;
            }
          const double diameter =
            cell.vertices[0].distance(cell.vertices[n_corners - 1]);
          for (const auto &corners : split)
            {
              Tensor<2, dim> J;
              for (unsigned int k = 0; k < dim; ++k)
                for (unsigned int d = 0; d < dim; ++d)
                  J[d][k] = cell.vertices[corners[k + 1]][d] -
                            cell.vertices[corners[0]][d];
              const double det = determinant(J);
              if (std::abs(det) <= 1e-12 * std::pow(diameter, dim))
                continue;
              const Tensor<2, dim>                inverse = invert(J);
              std::array<Tensor<1, dim>, dim + 1> gradient;
              gradient[0] = 0;
              for (unsigned int k = 0; k < dim; ++k)
                {
                  for (unsigned int d = 0; d < dim; ++d)
                    gradient[k + 1][d] = inverse[k][d];
                  gradient[0] -= gradient[k + 1];
                }
              std::array<unsigned int, dim + 1> simplex;
              for (unsigned int k = 0; k <= dim; ++k)
                simplex[k] = node[corners[k]];
              simplex_nodes.push_back(simplex);
              simplex_gradients.push_back(gradient);
              simplex_volumes.push_back(std::abs(det) / (dim == 2 ? 2. : 6.));
            }
        }
      set_active(std::vector<char>(points.size(), 1));
    }



    template <int dim>
    SimplexBand<dim>
    SimplexBand<dim>::gather(const LevelSetFields<dim> &fields,
                             const unsigned int         crack,
                             const BoundingBox<dim>    &box,
                             const MPI_Comm             communicator)
    {
      // Per cell: the vertices' coordinates, then lsn, then lst.
      constexpr unsigned int stride = (dim + 2) * n_corners;
      const auto            &lsn = fields.lsn(crack), &lst = fields.lst(crack);
      std::vector<double>    mine;
      for (const auto &cell : fields.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const BoundingBox<dim> b     = cell->bounding_box();
            bool                   meets = true;
            for (unsigned int d = 0; d < dim; ++d)
              meets = meets && b.upper_bound(d) >= box.lower_bound(d) &&
                      b.lower_bound(d) <= box.upper_bound(d);
            if (!meets)
              continue;
            for (unsigned int v = 0; v < n_corners; ++v)
              for (unsigned int d = 0; d < dim; ++d)
                mine.push_back(cell->vertex(v)[d]);
            for (const auto *field : {&lsn, &lst})
              for (unsigned int v = 0; v < n_corners; ++v)
                mine.push_back((*field)[cell->vertex_dof_index(v, 0)]);
          }
      std::vector<Cell> cells;
      for (const std::vector<double> &theirs :
           Utilities::MPI::all_gather(communicator, mine))
        for (std::size_t c = 0; c + stride <= theirs.size(); c += stride)
          {
            Cell cell;
            for (unsigned int v = 0; v < n_corners; ++v)
              {
                for (unsigned int d = 0; d < dim; ++d)
                  cell.vertices[v][d] = theirs[c + v * dim + d];
                cell.lsn[v] = theirs[c + dim * n_corners + v];
                cell.lst[v] = theirs[c + (dim + 1) * n_corners + v];
              }
            cells.push_back(cell);
          }
      return SimplexBand(std::move(cells));
    }



    template <int dim>
    std::size_t
    SimplexBand<dim>::size() const
    {
      return points.size();
    }



    template <int dim>
    Point<dim>
    SimplexBand<dim>::point(const std::size_t i) const
    {
      return points[i];
    }



    template <int dim>
    std::size_t
    SimplexBand<dim>::find(const Point<dim> &x) const
    {
      // The bins next to x's too: a node within the tolerance may lie
      // across a bin's face.
      const std::array<long long, dim> centre = bin(x);
      for (unsigned int n = 0; n < std::pow(3, dim); ++n)
        {
          std::array<long long, dim> key = centre;
          unsigned int               m   = n;
          for (unsigned int d = 0; d < dim; ++d, m /= 3)
            key[d] += static_cast<long long>(m % 3) - 1;
          const auto it = index.find(key);
          if (it != index.end() && points[it->second].distance(x) <= tolerance)
            return it->second;
        }
      return none;
    }



    template <int dim>
    std::array<long long, dim>
    SimplexBand<dim>::bin(const Point<dim> &x) const
    {
      std::array<long long, dim> key;
      for (unsigned int d = 0; d < dim; ++d)
        key[d] = static_cast<long long>(std::floor(x[d] / tolerance));
      return key;
    }



    template <int dim>
    void
    SimplexBand<dim>::set_active(const std::vector<char> &mask)
    {
      AssertDimension(mask.size(), points.size());
      active = mask;
      edge.assign(points.size(), 0);
      active_simplices.clear();
      node_simplices.assign(points.size(), {});
      height = std::numeric_limits<double>::max();
      for (unsigned int s = 0; s < simplex_nodes.size(); ++s)
        {
          bool all = true;
          for (const unsigned int i : simplex_nodes[s])
            all = all && active[i];
          if (!all)
            {
              for (const unsigned int i : simplex_nodes[s])
                edge[i] = active[i];
              continue;
            }
          for (const unsigned int i : simplex_nodes[s])
            node_simplices[i].push_back(active_simplices.size());
          active_simplices.push_back(s);
          double largest = 0;
          for (const Tensor<1, dim> &g : simplex_gradients[s])
            largest = std::max(largest, g.norm());
          height = std::min(height, 1. / largest);
        }
    }



    template <int dim>
    bool
    SimplexBand<dim>::is_active(const std::size_t i) const
    {
      return active[i];
    }



    template <int dim>
    bool
    SimplexBand<dim>::is_edge(const std::size_t i) const
    {
      return edge[i];
    }



    template <int dim>
    std::size_t
    SimplexBand<dim>::n_simplices() const
    {
      return active_simplices.size();
    }



    template <int dim>
    double
    SimplexBand<dim>::min_height() const
    {
      return height;
    }



    template class SimplexBand<2>;
    template class SimplexBand<3>;
  } // namespace LevelSetUpdate
} // namespace xcrack
