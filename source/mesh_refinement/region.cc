#include <xcrack/mesh_refinement/region.h>

namespace xcrack
{
  namespace MeshRefinement
  {
    template <int dim>
    void
    Region<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Region");
      prm.declare_entry("Region",
                        "0",
                        Patterns::Anything(),
                        "Expression of x, y, z, positive in the region to "
                        "refine, e.g. 0.1 - sqrt(x^2 + y^2).");
      prm.leave_subsection();
    }



    template <int dim>
    void
    Region<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Region");
      region = std::make_unique<ParsedVectorFunction<dim>>(
        prm.get("Region"),
        1,
        this->get_function_constants(),
        "Mesh refinement/Region/Region");
    }



    template <int dim>
    void
    Region<dim>::mark(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned() && region->value(cell->center()) > 0)
          cell->set_refine_flag();
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Region,
                           "region",
                           "every cell whose centre satisfies Region is "
                           "refined (subsection Region).")
  } // namespace MeshRefinement
} // namespace xcrack
