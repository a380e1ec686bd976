#ifndef xcrack_xfem_enrichment_h
#define xcrack_xfem_enrichment_h

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/affine_constraints.h>

#include <xcrack/crack/crack_geometry.h>

#include <map>
#include <memory>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * The jump function of a crack, H = sign(lsn): +1 on the side the normal
   * points to (and on the crack, lsn = 0), -1 on the other. Its gradient
   * vanishes away from the crack, which is all FE_Enriched needs (quadrature
   * points never lie on it).
   */
  template <int dim>
  class HeavisideFunction : public Function<dim>
  {
  public:
    explicit HeavisideFunction(const CrackGeometry<dim> &crack);

    double
    value(const Point<dim> &p, const unsigned int component = 0) const override;

    Tensor<1, dim>
    gradient(const Point<dim>  &p,
             const unsigned int component = 0) const override;

  private:
    const CrackGeometry<dim> &crack;
  };



  /**
   * The X-FEM enrichment of the displacement space by the jump of a crack
   * (Heaviside enrichment).
   *
   * The finite element space is an hp::FECollection of
   * FESystem(FE_Enriched(FE_Q(p), FE_Q(p), H), dim) elements: index 0 has
   * no enrichment (a dominating FE_Nothing fills the enrichment slot, so
   * enriched DoFs vanish where enriched and plain cells meet), index 1 is
   * enriched by H. This nesting is the one that works with hanging nodes
   * and hp interfaces in deal.II 9.4 (DESIGN.md, pitfalls).
   *
   * Cells are classified from the level sets at their vertices:
   *
   * - split: lsn changes sign and lst < 0 at every vertex (the crack runs
   *   through the cell);
   * - tip: lsn and lst both change sign (the front is in the cell);
   * - plain: everything else.
   *
   * A DoF is enriched if the support of its shape function contains a split
   * cell and no tip cell. Cells carry index 1 when any of their vertices
   * touches a split cell, and the enriched DoFs of such a cell that are not
   * enriched are constrained to zero: an unconstrained N_j H with H constant
   * on supp N_j would copy N_j and make the matrix singular.
   *
   * Split cells are integrated by a rule that is exact on each side of the
   * crack (deal.II's NonMatching::QuadratureGenerator on the Q1 interpolant
   * of lsn), cached per cell.
   *
   * Not yet: the crack-tip (branch function) enrichment, several cracks, a
   * crack mouth on a Dirichlet boundary, and the conditioning treatment of
   * cuts close to nodes.
   */
  template <int dim>
  class Enrichment
  {
  public:
    static constexpr unsigned int plain     = 0;
    static constexpr unsigned int heaviside = 1;

    /**
     * Enrich the displacement space of degree @p degree by the jump of
     * @p crack. A vertex is not enriched when the smaller side of its
     * support, cut by the crack, holds less than @p volume_tolerance of the
     * support's volume (the cut is too close to the vertex: its enriched
     * function would nearly copy the standard one).
     */
    Enrichment(const CrackGeometry<dim> &crack,
               const unsigned int        degree,
               const double              volume_tolerance);

    const hp::FECollection<dim> &
    get_fe_collection() const;

    /**
     * Classify the cells of @p dof_handler's mesh (owned and ghost) and set
     * the active FE index of the owned cells. Call before distribute_dofs().
     */
    void
    set_fe_indices(DoFHandler<dim> &dof_handler);

    /**
     * Add to @p constraints the zero constraints of the enriched DoFs that
     * are not enriched. Call after the hanging-node constraints and before
     * the Dirichlet ones.
     */
    void
    make_constraints(const DoFHandler<dim>     &dof_handler,
                     AffineConstraints<double> &constraints) const;

    /// Whether local DoF @p i of @p fe is an enriched one.
    static bool
    is_enriched_dof(const FiniteElement<dim> &fe, const unsigned int i);

    /// Whether @p cell is split by the crack (and has a special rule).
    bool
    is_split(const typename DoFHandler<dim>::active_cell_iterator &cell) const;

    /**
     * The quadrature rule of a split cell, exact for polynomials of degree
     * 2 @p n_points_1d - 1 on each side of the crack (in reference
     * coordinates). Built on first use and cached until the next
     * set_fe_indices().
     */
    const Quadrature<dim> &
    split_cell_quadrature(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const unsigned int                                    n_points_1d) const;

    /// The enriched DoFs of the locally owned and ghost cells.
    IndexSet
    enriched_dofs(const DoFHandler<dim> &dof_handler) const;

  private:
    enum class CellKind : unsigned char
    {
      plain,
      split,
      tip
    };

    const CrackGeometry<dim> &crack;
    const double              volume_tolerance;
    HeavisideFunction<dim>    heaviside_function;
    hp::FECollection<dim>     fe_collection;
    std::vector<CellKind>     cell_kind;
    /// Whether the functions of each vertex are enriched (vertices of the
    /// owned and ghost cells).
    std::vector<bool>                               enriched_vertex;
    mutable std::map<unsigned int, Quadrature<dim>> split_rules;
  };
} // namespace xcrack

#endif
