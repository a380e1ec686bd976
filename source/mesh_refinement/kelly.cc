#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/numerics/error_estimator.h>

#include <xcrack/input_error.h>
#include <xcrack/mesh_refinement/kelly.h>

namespace xcrack
{
  namespace MeshRefinement
  {
    template <int dim>
    void
    Kelly<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Kelly");
      {
        prm.declare_entry("Refine fraction",
                          "0.3",
                          Patterns::Double(0, 1),
                          "Fraction of cells refined.");
        prm.declare_entry("Coarsen fraction",
                          "0.0",
                          Patterns::Double(0, 1),
                          "Fraction of cells coarsened.");
      }
      prm.leave_subsection();
    }



    template <int dim>
    void
    Kelly<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Kelly");
      refine_fraction  = prm.get_double("Refine fraction");
      coarsen_fraction = prm.get_double("Coarsen fraction");
      check_input(refine_fraction + coarsen_fraction <= 1,
                  "Mesh refinement/Kelly/Refine fraction + Coarsen fraction "
                  "must not exceed 1.");
    }



    template <int dim>
    void
    Kelly<dim>::mark(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      if (this->get_enrichment() && !warned)
        {
          this->get_pcout()
            << "  Warning: Mesh refinement/Strategy = kelly reads the "
               "cracks' opening as error and refines their lips rather than "
               "their fronts; Strategy = residual treats the lips as "
               "boundaries."
            << std::endl;
          warned = true;
        }
      const DoFHandler<dim> &dof_handler = this->get_dof_handler();
      Vector<float>          indicators(triangulation.n_active_cells());
      const unsigned int     max_degree =
        dof_handler.get_fe_collection().max_degree();
      // One face rule per element of the (enriched) collection.
      hp::QCollection<dim - 1> face_rules;
      for (unsigned int i = 0; i < dof_handler.get_fe_collection().size(); ++i)
        face_rules.push_back(QGauss<dim - 1>(max_degree + 1));
      KellyErrorEstimator<dim>::estimate(
        dof_handler,
        face_rules,
        {},
        this->get_solution(),
        indicators,
        ComponentMask(),
        nullptr,
        numbers::invalid_unsigned_int,
        triangulation.locally_owned_subdomain());
      parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
        triangulation, indicators, refine_fraction, coarsen_fraction);
    }

    template <int dim>
    void
    Kelly<dim>::save(Plugins::State &state) const
    {
      state["warned"] = Plugins::pack(warned);
    }



    template <int dim>
    void
    Kelly<dim>::load(const Plugins::State &state)
    {
      warned = Plugins::unpack(state, "warned", warned);
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Kelly,
                           "kelly",
                           "a fixed fraction of the cells with the largest "
                           "Kelly indicator is refined (subsection Kelly); "
                           "it reads a crack's opening as error: with cracks, "
                           "use residual.")
  } // namespace MeshRefinement
} // namespace xcrack
