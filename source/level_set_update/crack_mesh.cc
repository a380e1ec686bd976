#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/mapping_q1.h>

#include <xcrack/crack/crack_set.h>
#include <xcrack/crack/crack_surface.h>
#include <xcrack/crack/facet_crack.h>
#include <xcrack/level_set_update/crack_mesh.h>
#include <xcrack/level_set_update/front_track.h>

#include <cmath>
#include <map>
#include <tuple>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    template <int dim>
    void
    CrackMesh<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Crack mesh");
      prm.declare_entry(
        "Write surface",
        "true",
        Patterns::Bool(),
        "Write the crack surface after each update as "
        "crack_mesh[i]-<step>.vtu: the facets with the step that added "
        "them and their normal, and the fronts.");
      prm.leave_subsection();
    }



    template <int dim>
    void
    CrackMesh<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Crack mesh");
      write_surface = prm.get_bool("Write surface");
    }



    namespace
    {
      /// The lips of @p surface as facets: segments, or polygons split into
      /// triangles around their first corner.
      template <int dim>
      std::vector<typename FacetSurface<dim>::Facet>
      facets_of_lips(const CrackSurface<dim> &surface)
      {
        std::vector<typename FacetSurface<dim>::Facet> facets;
        for (const auto &[corners, normal] : surface.lips())
          if constexpr (dim == 2)
            facets.push_back({{{corners[0], corners[1]}}, normal, 0});
          else
            for (unsigned int k = 1; k + 1 < corners.size(); ++k)
              facets.push_back(
                {{{corners[0], corners[k], corners[k + 1]}}, normal, 0});
        return facets;
      }
    } // namespace



    template <int dim>
    std::vector<std::vector<typename CrackMesh<dim>::Start>>
    CrackMesh<dim>::starting_points(const unsigned int crack) const
    {
      using FrontNode                  = typename FacetSurface<dim>::FrontNode;
      const FacetSurface<dim> &surface = surfaces[crack];
      const auto &fronts = this->get_crack_surfaces()[crack].fronts();
      std::vector<std::vector<Start>> starts(fronts.size());
      bool                            own =
        !surface.fronts().empty() && surface.fronts().size() == fronts.size();
      if (own)
        for (const auto &nodes : surface.fronts())
          {
            const unsigned int f =
              std::get<0>(project(fronts, nodes[nodes.size() / 2].position));
            own = own && starts[f].empty();
            if (!own)
              break;
            const std::vector<std::vector<FrontPoint<dim>>> chain = {fronts[f]};
            for (const FrontNode &node : nodes)
              starts[f].push_back(
                {node.position, std::get<1>(project(chain, node.position))});
            // Where the nodes have drifted apart (a growing front), points
            // in between, about as far apart as the extracted points.
            if (dim == 3 && fronts[f].size() > 1)
              {
                const double spacing =
                  fronts[f].back().s / (fronts[f].size() - 1);
                std::vector<Start> dense;
                for (unsigned int k = 0; k < starts[f].size(); ++k)
                  {
                    if (k > 0)
                      {
                        const Point<dim> a = starts[f][k - 1].x,
                                         b = starts[f][k].x;
                        const unsigned int n =
                          std::ceil(a.distance(b) / spacing - 0.5);
                        for (unsigned int j = 1; j < n; ++j)
                          {
                            const Point<dim> x = a + (b - a) * j / n;
                            dense.push_back(
                              {x, std::get<1>(project(chain, x))});
                          }
                      }
                    dense.push_back(starts[f][k]);
                  }
                starts[f] = dense;
              }
          }
      if (!own)
        for (unsigned int f = 0; f < fronts.size(); ++f)
          {
            starts[f].clear();
            for (const FrontPoint<dim> &p : fronts[f])
              starts[f].push_back({p.position, p.s});
          }

      return starts;
    }



    template <int dim>
    void
    CrackMesh<dim>::extend(const unsigned int                 crack,
                           const std::vector<FrontMove<dim>> &moves)
    {
      using Facet                = typename FacetSurface<dim>::Facet;
      using FrontNode            = typename FacetSurface<dim>::FrontNode;
      FacetSurface<dim> &surface = surfaces[crack];
      const auto        &fronts  = this->get_crack_surfaces()[crack].fronts();
      double             largest;
      const std::vector<Track<dim>> tracks =
        make_tracks(crack, moves, fronts, largest);
      const unsigned int step = this->get_step() + 1;

      const std::vector<std::vector<Start>> starts = starting_points(crack);

      std::vector<Facet>                  strip;
      std::vector<std::vector<FrontNode>> new_fronts;
      for (unsigned int f = 0; f < fronts.size(); ++f)
        {
          new_fronts.emplace_back();
          if (tracks[f].s.empty())
            {
              // A front without moves stays where it is.
              for (const FrontPoint<dim> &p : fronts[f])
                new_fronts.back().push_back({p.position, p.e1 / p.e1.norm()});
              continue;
            }
          // e2 of the frame of K need not point to the lsn > 0 side (in 2D
          // it is e1 turned by +90 degrees): the surface's normals at the
          // front say which way it points.
          double agreement = 0;
          for (const Start &p : starts[f])
            agreement +=
              surface.nearest(p.x).second * tracks[f].at(p.s).old_normal();
          const double sign = (agreement < 0 ? -1. : 1.);

          std::vector<Point<dim>>     from, to;
          std::vector<Tensor<1, dim>> normals;
          for (const Start &p : starts[f])
            {
              const Sample<dim>    sample    = tracks[f].at(p.s);
              const Tensor<1, dim> direction = sample.new_direction();
              from.push_back(p.x);
              to.push_back(p.x + sample.advance * direction);
              normals.push_back(sign * sample.new_normal());
              new_fronts.back().push_back({to.back(), direction});
            }
          if constexpr (dim == 2)
            for (unsigned int k = 0; k < from.size(); ++k)
              strip.push_back({{{from[k], to[k]}}, normals[k], step});
          else
            for (unsigned int k = 0; k + 1 < from.size(); ++k)
              {
                // The quadrilateral swept by a segment of the front, as two
                // triangles oriented by the mean normal of its ends.
                const Tensor<1, dim> mean = normals[k] + normals[k + 1];
                for (const auto &corners :
                     {std::array<Point<dim>, dim>{
                        {from[k], from[k + 1], to[k + 1]}},
                      std::array<Point<dim>, dim>{{from[k], to[k + 1], to[k]}}})
                  {
                    Tensor<1, dim> n;
                    if constexpr (dim == 3)
                      n = cross_product_3d(corners[1] - corners[0],
                                           corners[2] - corners[0]);
                    if (n.norm() == 0)
                      continue;
                    n *= (n * mean < 0 ? -1. : 1.) / n.norm();
                    strip.push_back({corners, n, step});
                  }
              }
        }
      surface.add(strip);
      surface.set_fronts(new_fronts);
    }



    template <int dim>
    void
    CrackMesh<dim>::update(const unsigned int                 crack,
                           const std::vector<FrontMove<dim>> &moves,
                           LevelSetFields<dim>               &fields)
    {
      double largest = 0;
      for (const FrontMove<dim> &m : moves)
        if (m.crack == crack)
          largest = std::max(largest, m.advance);
      if (largest == 0)
        return;
      if (surfaces.size() < fields.n_cracks())
        surfaces.resize(fields.n_cracks());
      FacetSurface<dim> &surface = surfaces[crack];
      // A crack started from a surface this update wrote grows on from it;
      // any other from the lips its fields draw.
      if (surface.empty())
        {
          const auto *start = dynamic_cast<const FacetCrack<dim> *>(
            &this->get_initial_cracks()[crack]);
          if (start)
            surface = start->surface();
          else
            surface.add(facets_of_lips(this->get_crack_surfaces()[crack]));
        }
      AssertThrow(!surface.empty(),
                  ExcMessage("The crack mesh level-set update found no lips "
                             "of crack " +
                             std::to_string(crack + 1) + " to start from."));
      extend(crack, moves);

      // The level sets anew on every owned node.
      const DoFHandler<dim> &dof_handler = fields.get_dof_handler();
      std::map<types::global_dof_index, Point<dim>> support;
      DoFTools::map_dofs_to_support_points(MappingQ1<dim>(),
                                           dof_handler,
                                           support);
      const IndexSet                owned = dof_handler.locally_owned_dofs();
      const MPI_Comm                comm  = this->get_mpi_communicator();
      TrilinosWrappers::MPI::Vector lsn(owned, comm), lst(owned, comm);
      for (const types::global_dof_index dof : owned)
        {
          const Point<dim> &x = support.at(dof);
          lsn[dof]            = surface.lsn(x);
          lst[dof]            = surface.lst(x);
        }
      lsn.compress(VectorOperation::insert);
      lst.compress(VectorOperation::insert);
      fields.set(crack, lsn, lst);

      if (write_surface)
        this->write_output_file(
          "crack_mesh" +
            (fields.n_cracks() > 1 ? std::to_string(crack + 1) :
                                     std::string()) +
            "-" + Utilities::int_to_string(this->get_step() + 1, 3) + ".vtu",
          [&](std::ostream &out) { surface.write_vtu(out); });
    }



    template <int dim>
    void
    CrackMesh<dim>::save(Plugins::State &state) const
    {
      state["surfaces"] = Plugins::pack(surfaces);
    }



    template <int dim>
    void
    CrackMesh<dim>::load(const Plugins::State &state)
    {
      surfaces = Plugins::unpack(state, "surfaces", surfaces);
    }



    XCRACK_REGISTER_PLUGIN(Interface,
                           CrackMesh,
                           "crack mesh",
                           "the crack as an explicit surface (segments in "
                           "2D, triangles in 3D) extended each step by the "
                           "strip its fronts sweep; the level sets by "
                           "projection on it everywhere (subsection Crack "
                           "mesh).")
  } // namespace LevelSetUpdate
} // namespace xcrack
