#include <deal.II/base/quadrature_lib.h>

#include <deal.II/distributed/grid_refinement.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/numerics/error_estimator.h>

#include <xcrack/input_error.h>
#include <xcrack/refinement.h>

namespace xcrack
{
  template <int dim>
  void
  Refinement<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh refinement");
    {
      prm.declare_entry("Number of cycles",
                        "1",
                        Patterns::Integer(1, 50),
                        "Number of solves; the mesh is refined between two "
                        "of them.");
      prm.declare_entry("Strategy",
                        "global",
                        Patterns::Selection("global|kelly|region|front"),
                        "How the mesh is refined between cycles.");
      prm.declare_entry("Refine fraction",
                        "0.3",
                        Patterns::Double(0, 1),
                        "Kelly: fraction of cells refined.");
      prm.declare_entry("Coarsen fraction",
                        "0.0",
                        Patterns::Double(0, 1),
                        "Kelly: fraction of cells coarsened.");
      prm.declare_entry("Region",
                        "0",
                        Patterns::Anything(),
                        "Region: expression of x, y, z, positive in the "
                        "region to refine, e.g. 0.1 - sqrt(x^2 + y^2).");
      prm.declare_entry("Front band",
                        "2",
                        Patterns::Double(0),
                        "Front: refine the cells whose centre lies within "
                        "this many of their own diameters of a crack front "
                        "(r = sqrt(lsn^2 + lst^2)).");
      prm.declare_entry("Maximum level",
                        "12",
                        Patterns::Integer(0, 30),
                        "Cells at this refinement level are not refined "
                        "further.");
    }
    prm.leave_subsection();
  }



  template <int dim>
  void
  Refinement<dim>::parse_parameters(ParameterHandler        &prm,
                                    const FunctionConstants &constants)
  {
    std::string region_text;
    prm.enter_subsection("Mesh refinement");
    {
      n_cycles         = prm.get_integer("Number of cycles");
      strategy         = prm.get("Strategy");
      refine_fraction  = prm.get_double("Refine fraction");
      coarsen_fraction = prm.get_double("Coarsen fraction");
      region_text      = prm.get("Region");
      max_level        = prm.get_integer("Maximum level");
      front_band       = prm.get_double("Front band");
    }
    prm.leave_subsection();

    check_input(refine_fraction + coarsen_fraction <= 1,
                "Mesh refinement/Refine fraction + Coarsen fraction must not "
                "exceed 1.");

    region.reset();
    if (strategy == "region")
      region = std::make_unique<ParsedVectorFunction<dim>>(
        region_text, 1, constants, "Mesh refinement/Region");
  }



  template <int dim>
  void
  Refinement<dim>::refine(
    parallel::distributed::Triangulation<dim>       &triangulation,
    const DoFHandler<dim>                           &dof_handler,
    const TrilinosWrappers::MPI::Vector             &solution,
    const std::function<double(const Point<dim> &)> &front_distance) const
  {
    if (strategy == "global")
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            cell->set_refine_flag();
      }
    else if (strategy == "kelly")
      {
        Vector<float>      indicators(triangulation.n_active_cells());
        const unsigned int max_degree =
          dof_handler.get_fe_collection().max_degree();
        // One face rule per element of the (enriched) collection.
        hp::QCollection<dim - 1> face_rules;
        for (unsigned int i = 0; i < dof_handler.get_fe_collection().size();
             ++i)
          face_rules.push_back(QGauss<dim - 1>(max_degree + 1));
        KellyErrorEstimator<dim>::estimate(
          dof_handler,
          face_rules,
          {},
          solution,
          indicators,
          ComponentMask(),
          nullptr,
          numbers::invalid_unsigned_int,
          triangulation.locally_owned_subdomain());
        parallel::distributed::GridRefinement::refine_and_coarsen_fixed_number(
          triangulation, indicators, refine_fraction, coarsen_fraction);
      }
    else if (strategy == "front")
      {
        AssertThrow(front_distance, ExcInternalError());
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() &&
              front_distance(cell->center()) < front_band * cell->diameter())
            cell->set_refine_flag();
      }
    else
      {
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned() && region->value(cell->center()) > 0)
            cell->set_refine_flag();
      }

    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned() && cell->level() >= int(max_level))
        cell->clear_refine_flag();

    triangulation.execute_coarsening_and_refinement();
  }



  template class Refinement<2>;
  template class Refinement<3>;
} // namespace xcrack
