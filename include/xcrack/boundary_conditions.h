#ifndef xcrack_boundary_conditions_h
#define xcrack_boundary_conditions_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/fe/component_mask.h>
#include <deal.II/grid/tria.h>

#include <xcrack/parsed_function.h>

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * Loads and supports of the elasticity problem (`subsection Boundary
   * conditions`): prescribed displacements and tractions per boundary id,
   * a body force, a pressure on the crack lips, and pinned vertices. Each
   * boundary entry is a list of `id: expr_x; expr_y[; expr_z]` items separated
   * by `|`, e.g.
   *
   *     set Dirichlet = 0: 0; 0 | 1: 0.01*y; 0
   *     set Dirichlet components = 1: x
   *     set Neumann = 3: 0; -1
   *
   * `Dirichlet components` restricts the prescribed components of a boundary
   * (letters among x, y, z): a roller is `2: y`. Expressions may use x, y, z,
   * pi, the material constants E, nu, mu, lambda and the `Function
   * constants` of the file. `id: exact` takes the values of the exact
   * solution (`subsection Exact solution`).
   */
  template <int dim>
  class BoundaryConditions
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Parse the entries into functions; throws InputError naming the entry.
     * A Dirichlet item whose value is `exact` takes @p exact_solution.
     */
    void
    parse_parameters(ParameterHandler                     &prm,
                     const FunctionConstants              &constants,
                     const std::shared_ptr<Function<dim>> &exact_solution);

    /**
     * Declare the entries of another load set of the same scene (in the
     * current subsection): Dirichlet, Neumann, Body force, Lip pressure.
     */
    static void
    declare_load_set(ParameterHandler &prm);

    /**
     * Parse another load set of the scene (declare_load_set(), in the
     * subsection @p prm is in, which @p section names in messages) on the
     * supports of @p supports: the supports of a body do not change within
     * a load cycle, so its Dirichlet boundaries, their components and its
     * pinned points are taken over, and the set gives only values. A
     * Dirichlet boundary of @p supports that the set does not list holds
     * zero displacement; the set may list no other.
     */
    void
    parse_load_set(ParameterHandler         &prm,
                   const std::string        &section,
                   const BoundaryConditions &supports,
                   const FunctionConstants  &constants);

    /// Whether the set has no load at all (no entry given).
    bool
    empty() const;

    /**
     * Check the boundary ids against those of @p triangulation: every id
     * named must exist (on some rank), and a component may not be given both
     * a displacement and a traction on the same boundary.
     */
    void
    check_against(const Triangulation<dim> &triangulation) const;

    /**
     * Evaluate the data where the assembly will use it on @p triangulation
     * (the Dirichlet data at the vertices of its faces, the Dirichlet and
     * Neumann data at the Gauss points, @p degree + 1 per direction, of
     * the faces of their boundaries, the body force at the Gauss points of
     * the cells) and throw an InputError naming the first entry and point
     * where a value is not finite (collective). Returns the displacement the
     * loads can produce at most, in order of magnitude, on a body of
     * diameter @p size and Young's modulus @p youngs_modulus: max |g| +
     * (max |t| + max |p|) size / E + max |f| size^2 / E (g Dirichlet data,
     * t tractions, p the lip pressure at the vertices where it is finite,
     * f the body force). The Simulator compares the solution with it: a
     * displacement a million times larger comes from a singular system.
     */
    double
    check_finite(const Triangulation<dim> &triangulation,
                 const unsigned int        degree,
                 const double              size,
                 const double              youngs_modulus) const;

    /**
     * Throw an InputError when the Dirichlet data and the pinned points
     * leave a rigid-body motion of the uncracked body free (rollers on one
     * face only, say): the stiffness matrix would be singular, and a direct
     * solver would return round-off divided by a zero pivot. The motions
     * (dim translations, dim (dim - 1) / 2 rotations) restricted to the held
     * components at the held vertices must have full rank (collective).
     * A piece that a crack cuts loose is only seen after the solve.
     */
    void
    check_rigid_body_motions(const Triangulation<dim> &triangulation,
                             const double              size) const;

    /// The subsection these loads come from, for messages.
    std::string section = "Boundary conditions";

    std::map<types::boundary_id, std::shared_ptr<Function<dim>>> dirichlet;
    std::map<types::boundary_id, ComponentMask>                  dirichlet_mask;
    std::map<types::boundary_id, std::unique_ptr<Function<dim>>> neumann;
    std::unique_ptr<Function<dim>>                               body_force;
    /// Pressure on the crack lips (null: traction-free lips).
    std::unique_ptr<Function<dim>> lip_pressure;
    /// Vertices with components held at zero.
    std::vector<std::pair<Point<dim>, ComponentMask>> pinned;

  private:
    /// Whether some load was given (empty()).
    bool given = true;
  };
} // namespace xcrack

#endif
