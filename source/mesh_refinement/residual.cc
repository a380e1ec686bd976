#include <deal.II/distributed/grid_refinement.h>

#include <xcrack/input_error.h>
#include <xcrack/material.h>
#include <xcrack/mesh_refinement/residual.h>
#include <xcrack/xfem/residual_estimator.h>

namespace xcrack
{
  namespace MeshRefinement
  {
    template <int dim>
    void
    Residual<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Residual");
      {
        prm.declare_entry(
          "Marking",
          "fixed number",
          Patterns::Selection("fixed number|fixed fraction"),
          "fixed number: refine (coarsen) the Refine (Coarsen) fraction "
          "of the cells with the largest (smallest) indicators; fixed "
          "fraction: refine the fewest cells that hold the Refine fraction "
          "of the estimated squared error, coarsen those that hold the "
          "Coarsen fraction of it.");
        prm.declare_entry("Refine fraction",
                          "0.3",
                          Patterns::Double(0, 1),
                          "Fraction of cells refined (or of the squared "
                          "error, with fixed fraction marking).");
        prm.declare_entry("Coarsen fraction",
                          "0.0",
                          Patterns::Double(0, 1),
                          "Fraction of cells coarsened (or of the squared "
                          "error).");
      }
      prm.leave_subsection();
    }



    template <int dim>
    void
    Residual<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Residual");
      fixed_fraction   = (prm.get("Marking") == "fixed fraction");
      refine_fraction  = prm.get_double("Refine fraction");
      coarsen_fraction = prm.get_double("Coarsen fraction");
      check_input(refine_fraction + coarsen_fraction <= 1,
                  "Mesh refinement/Residual/Refine fraction + Coarsen "
                  "fraction must not exceed 1.");
    }



    template <int dim>
    void
    Residual<dim>::mark(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      const Material              &material = this->get_material();
      const ResidualEstimator<dim> estimator(this->get_enrichment(),
                                             this->get_boundary_conditions(),
                                             material.lambda(dim),
                                             material.mu());
      Vector<float>                indicators;
      estimator.estimate(this->get_dof_handler(),
                         this->get_solution(),
                         indicators);
      if (fixed_fraction)
        parallel::distributed::GridRefinement::
          refine_and_coarsen_fixed_fraction(triangulation,
                                            indicators,
                                            refine_fraction,
                                            coarsen_fraction,
                                            VectorTools::L2_norm);
      else
        parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
          triangulation, indicators, refine_fraction, coarsen_fraction);
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Residual,
                           "residual",
                           "refine where the face residuals of the elastic "
                           "tractions are largest, the cracks' lips taken as "
                           "boundaries (subsection Residual).")
  } // namespace MeshRefinement
} // namespace xcrack
