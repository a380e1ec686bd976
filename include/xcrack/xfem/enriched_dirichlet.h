#ifndef xcrack_xfem_enriched_dirichlet_h
#define xcrack_xfem_enriched_dirichlet_h

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/lac/affine_constraints.h>

#include <xcrack/boundary_conditions.h>
#include <xcrack/crack/crack_geometry.h>
#include <xcrack/xfem/enrichment.h>

namespace xcrack
{
  using namespace dealii;

  /**
   * Dirichlet constraints for an X-FEM space.
   *
   * Interpolation treats enriched DoFs as nodal values, which they are not:
   * with unshifted enrichment the trace of u_h at a node is
   * s + sum_j phi_j(x) a_j (standard DoF s, enriched DoFs a_j, phi_j = H or a
   * branch function, evaluated on the side of the face). So where a
   * Dirichlet node carries free enriched DoFs:
   *
   * - jump (Heaviside) DoFs: on one side of the crack s = g - H a, a stays
   *   free; at a crack mouth, where the data take two values g+ and g-,
   *   s = (g+ + g-)/2 and a = (g+ - g-)/2 (DESIGN.md, pitfalls). Vertex and,
   *   for Q2, edge and face DoFs alike.
   * - branch DoFs (vertices only): s and the four a_j are fitted to the data
   *   by least squares on the Dirichlet faces around the vertex. A nodal
   *   condition alone would leave the branch DoFs free, and the face free to
   *   deform between the nodes right where the front meets it (measured on
   *   Case 1 in 3D: 0.26 energy error instead of 0.14, a boundary layer at
   *   the faces z = +-1); zeroing them would smear the singular field
   *   instead. With DOF gathering the branch DoFs are shared by the whole
   *   zone and only the standard DoF is constrained, nodally.
   *
   * Call after the hanging-node and enrichment constraints: a node carries
   * one copy of its DoFs per element used around it, tied together by the
   * former, and the copy that stays free is the one constrained here.
   */
  template <int dim>
  void
  make_enriched_dirichlet_constraints(
    const DoFHandler<dim>         &dof_handler,
    const Enrichment<dim>         &enrichment,
    const BoundaryConditions<dim> &boundary_conditions,
    AffineConstraints<double>     &constraints);
} // namespace xcrack

#endif
