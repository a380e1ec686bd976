#ifndef xcrack_refinement_h
#define xcrack_refinement_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/trilinos_vector.h>

#include <xcrack/parsed_function.h>

#include <functional>
#include <memory>

namespace xcrack
{
  using namespace dealii;

  /**
   * How the mesh changes between solves (`subsection Mesh refinement`).
   * A run does `Number of cycles` solves; before each solve but the first
   * the mesh is refined by one of:
   *
   * - `global`: every cell is split;
   * - `kelly`: a fixed fraction of the cells with the largest Kelly error
   *   indicator is refined (and a fraction coarsened);
   * - `region`: every cell whose centre satisfies `Region` (an expression of
   *   x, y, z that is positive inside) is refined, the way one refines around
   *   a crack front;
   * - `front`: every cell whose centre lies within `Front band` of its own
   *   diameters of a crack front: the refined zone shrinks with the cells,
   *   so each cycle adds cells along the front only (a 3D front gets about
   *   twice as many, not eight times).
   */
  template <int dim>
  class Refinement
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    void
    parse_parameters(ParameterHandler &prm, const FunctionConstants &constants);

    /**
     * Mark and refine @p triangulation. @p solution must have ghost entries
     * (it is only read by the Kelly estimator); @p front_distance gives the
     * distance of a point to the nearest crack front (read by `front`).
     */
    void
    refine(parallel::distributed::Triangulation<dim>       &triangulation,
           const DoFHandler<dim>                           &dof_handler,
           const TrilinosWrappers::MPI::Vector             &solution,
           const std::function<double(const Point<dim> &)> &front_distance = {})
      const;

    unsigned int n_cycles         = 1;
    std::string  strategy         = "global";
    double       refine_fraction  = 0.3;
    double       coarsen_fraction = 0.0;
    unsigned int max_level        = 12;
    double       front_band       = 2;

  private:
    std::unique_ptr<ParsedVectorFunction<dim>> region;
  };
} // namespace xcrack

#endif
