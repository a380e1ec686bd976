#ifndef xcrack_xfem_enrichment_h
#define xcrack_xfem_enrichment_h

#include <deal.II/base/function.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_handler.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/non_matching/immersed_surface_quadrature.h>

#include <xcrack/crack/crack_geometry.h>
#include <xcrack/crack/level_set_fields.h>
#include <xcrack/xfem/branch_functions.h>
#include <xcrack/xfem/cell_level_sets.h>

#include <array>
#include <map>
#include <memory>
#include <set>
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
    explicit HeavisideFunction(const LevelSetFunctions<dim> &crack);

    double
    value(const Point<dim> &p, const unsigned int component = 0) const override;

    Tensor<1, dim>
    gradient(const Point<dim>  &p,
             const unsigned int component = 0) const override;

  private:
    const LevelSetFunctions<dim> &crack;
  };



  /**
   * The choices of `subsection Enrichment`: which nodes get which functions
   * and how the cells the front touches are integrated.
   */
  struct EnrichmentParameters
  {
    /// Which nodes carry the crack-tip branch functions.
    enum class TipZone
    {
      /// None: the crack is represented by its jump only, and the cells
      /// the front touches are not enriched (energy error ~ h^(1/2)).
      none,
      /// The nodes of the cells the front touches (error still ~ h^(1/2),
      /// but a far smaller constant).
      topological,
      /// Also every node within `Enrichment radius` of the front: the
      /// optimal rate h^1 for Q1, at the cost of a zone of enriched DoFs
      /// that does not shrink with h (and of conditioning).
      geometric
    };

    double heaviside_volume_tolerance = 1e-9;
    /// Fit-to-vertex: a vertex closer to the crack surface than this
    /// fraction of its shortest adjacent edge is moved onto it (0: off).
    double       fit_to_vertex         = 0.01;
    TipZone      tip_zone              = TipZone::topological;
    double       radius                = 0;
    unsigned int tip_quadrature_points = 6;
    /// Gauss points per direction in the branch-only cells near the front
    /// that it does not touch (0: graded by the tolerance below).
    unsigned int near_front_quadrature_points = 0;
    /// Those cells with Gauss rules graded by their distance from the
    /// front, for this relative error (0: the tip rule there too).
    double near_front_quadrature_tolerance = 1e-6;
    bool   gather                          = false;
    /// Gathering: master spacing along a 3D front, in multiples of the
    /// largest tip cell's diameter.
    double gather_segment = 2;

    static void
    declare_parameters(ParameterHandler &prm);

    /// Read the entries; InputError names a radius that does not fit the
    /// zone choice.
    void
    parse_parameters(ParameterHandler &prm);
  };



  /**
   * The X-FEM enrichment of the displacement space by a crack: the jump
   * (Heaviside) function H on the nodes whose support the crack cuts, and
   * the four branch functions F1..F4 (BranchFunction) on the nodes of the
   * crack-tip zone.
   *
   * The finite element space is an hp::FECollection of
   * FESystem(FE_Enriched(FE_Q(p), {FE_Q(p), FE_Q(1)}, {{H}, {F1..F4}}), dim)
   * elements that all share this structure; a dominating FE_Nothing fills
   * the slots a cell does not use (so enriched DoFs vanish where cells of
   * different kinds meet). Index = plain (0), heaviside (1), tip (2), both
   * (3). This nesting is the one that works with hanging nodes and hp
   * interfaces in deal.II 9.4 (DESIGN.md, pitfalls). The branch functions
   * multiply Q1 shape functions also for Q2: they carry the singularity,
   * and only vertex DoFs make the Dirichlet treatment at the front simple.
   *
   * Cells are classified from the values of the cracks' level-set fields
   * (LevelSetFields) at their vertices, and every enriched cell evaluates
   * the jump and branch functions of the interpolants of those values
   * (CellLevelSets): the crack the rules integrate on. The classification:
   *
   * - tip: the front {lsn = 0, lst = 0} of the Q1 interpolants touches the
   *   closed cell (CellQuadrature::front_points), also when the front runs
   *   through a vertex or along an edge;
   * - split: otherwise lsn changes sign and its zero set lies on the crack
   *   (lst < 0 where it crosses the cell's edges);
   * - plain: everything else.
   *
   * A node is tip-enriched if it is a vertex of a tip cell or (geometric
   * zone) lies within the enrichment radius of the front, r = sqrt(lsn^2 +
   * lst^2) <= radius. It is Heaviside-enriched if its support contains a
   * split cell and it is neither tip-enriched nor a vertex of a tip cell,
   * unless the smaller side of the crack holds at most `Heaviside volume
   * tolerance` of that support, N_j H then being almost a copy of N_j. The
   * support counts what the function reaches: the vertex's cells and,
   * through the hanging-node constraints, those of its hanging neighbours;
   * the sides are measured with the rule the assembly uses (near the front
   * the tip rule, which need not see a thin sliver of the exact cut). Both
   * were needed on tilted 3D fronts through refined meshes, where a
   * function kept for a sliver only a constraint reached made the matrix
   * singular.
   * The enriched DoFs of cells with an enriched element that are not
   * enriched are constrained to zero: an unconstrained N_j H with H constant
   * on supp N_j would copy N_j and make the matrix singular.
   *
   * Split cells are integrated by a rule that is exact on each side of the
   * crack; tip cells, and cells within a diameter of the front, by the fan
   * rule of CellQuadrature::tip_cell_rule; all are cached per cell. For Q2
   * the jump DoFs of edges and faces follow their support (split, straddling
   * the crack beyond the volume tolerance, no tip cell), also inside the
   * tip zone.
   *
   * DOF gathering (`Gather tip DoFs`): the branch DoFs of each function
   * and component are tied, over the tip zone, to those of a few master
   * nodes along each front (FrontGathering: one per 2D tip, one about every
   * `Gather segment length` along a 3D front, linear in between), so the
   * zone carries F_k chi times a coefficient that varies along the front,
   * at the cost of 4 x dim unknowns per master instead of per node. The
   * masters are picked the same on every rank; their DoFs may be owned
   * elsewhere (gathering_masters(): the sparsity pattern needs their rows).
   *
   * Fit to vertex (`Fit to vertex tolerance` tau > 0): where the crack
   * passes within tau times the shortest adjacent edge of a vertex (on
   * the crack side of the front), the crack is moved through the vertex:
   * its lsn value there becomes zero, in the rules, the classification and
   * the enrichment functions of the cells around that vertex alike (and,
   * through lsn_shift(), in the fields). The cut then runs through the node
   * instead of leaving a sliver of relative size tau, which bounds the
   * smallest side of a cut support away from zero; the crack moves by at
   * most tau h. It complements the volume criterion, which drops the jump
   * of slivers the tolerance does not reach.
   *
   * Several cracks share the four FE indices: each cell evaluates the
   * functions of one crack (crack_of()), the one whose cut, front or
   * enriched nodes it holds. This is the "colouring" of enrichment zones
   * that Code_Aster and deal.II's ColorEnriched use: it is exact as long as
   * no cell needs the functions of two cracks, i.e. the enriched zones of
   * different cracks are at least one cell apart. Where they meet,
   * set_fe_indices() stops with an InputError naming both cracks and the
   * place (on every rank), rather than silently dropping one crack's
   * functions; refining between the cracks separates the zones.
   *
   * Not yet: shifted enrichment; crossing or
   * branching cracks (overlapping zones).
   *
   * Its member functions live in three files: enrichment.cc (the element,
   * the classification, the constraints), enrichment_gathering.cc (DOF
   * gathering) and enrichment_quadrature.cc (the cells' rules).
   */
  template <int dim>
  class Enrichment
  {
  public:
    static constexpr unsigned int plain     = 0;
    static constexpr unsigned int heaviside = 1;
    static constexpr unsigned int tip       = 2;
    static constexpr unsigned int both      = 3;
    /// No crack (in a cell or vertex map): cracks are numbered below it.
    static constexpr unsigned char invalid_crack = 255;

    /**
     * Enrich the displacement space of degree @p degree by @p n_cracks
     * cracks, whose level-set fields set_fe_indices() reads.
     */
    Enrichment(const unsigned int          n_cracks,
               const unsigned int          degree,
               const EnrichmentParameters &parameters);

    const hp::FECollection<dim> &
    get_fe_collection() const;

    const EnrichmentParameters &
    get_parameters() const;

    /**
     * Classify the cells of @p dof_handler's mesh (owned and ghost) by the
     * cracks' @p fields (on the same mesh) and set the active FE index of
     * the owned cells. Call before distribute_dofs().
     */
    void
    set_fe_indices(DoFHandler<dim>           &dof_handler,
                   const LevelSetFields<dim> &fields);

    /**
     * Add to @p constraints the zero constraints of the enriched DoFs that
     * are not enriched, and with gathering the ties of the branch DoFs to
     * masters along @p fronts (per crack, as CrackSurface::fronts() gives
     * them; only read with gathering). Call after the hanging-node
     * constraints and before the Dirichlet ones (collective).
     */
    void
    make_constraints(
      const DoFHandler<dim>                                        &dof_handler,
      AffineConstraints<double>                                    &constraints,
      const std::vector<std::vector<std::vector<FrontPoint<dim>>>> &fronts =
        {});

    /**
     * With gathering, after make_constraints(): the branch DoFs tied to
     * masters (those of owned cells), and the masters' DoFs (all of them,
     * on every rank; rows of the matrix that assembly writes to).
     */
    const IndexSet &
    gathered() const;
    const IndexSet &
    gathering_masters() const;

    /// Whether local DoF @p i of @p fe is an enriched one.
    static bool
    is_enriched_dof(const FiniteElement<dim> &fe, const unsigned int i);

    /**
     * The function that multiplies the shape function of local DoF @p i of
     * @p cell's element: H or one of F1..F4 of the cell's crack; nullptr
     * for a standard DoF.
     */
    const Function<dim> *
    enrichment_function(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const unsigned int                                    i) const;

    /**
     * The index of the crack whose functions @p cell evaluates (0 for a
     * cell no crack enriches). Valid after set_fe_indices() for owned and
     * ghost cells.
     */
    unsigned int
    crack_index(const typename Triangulation<dim>::cell_iterator &cell) const;

    /**
     * Fit to vertex: lsn_shift()[c][v] is subtracted from crack c's lsn at
     * vertex v of the triangulation (its lsn there if the crack was moved
     * through the vertex, else 0; an empty vector when nothing moved).
     */
    const std::vector<std::vector<double>> &
    lsn_shift() const;

    /**
     * The level sets whose functions @p cell evaluates (those of its crack,
     * see crack_index(), fitted to vertices): only for the cells with
     * enriched functions (a non-plain FE index), owned or ghost.
     */
    const LevelSetFunctions<dim> &
    crack_of(const typename Triangulation<dim>::cell_iterator &cell) const;

    /**
     * The values (lsn, lst) of @p cell's crack at its vertices, fitted to
     * vertices: what its rules are built from (owned and ghost cells).
     */
    std::pair<std::vector<double>, std::vector<double>>
    level_set_values(
      const typename Triangulation<dim>::cell_iterator &cell) const;

    /// Whether @p cell is split by the crack (and has a special rule).
    bool
    is_split(const typename DoFHandler<dim>::active_cell_iterator &cell) const;

    /**
     * What the crack does to @p cell, for output: 0 nothing, 1 splits it,
     * 2 its front touches it, 3 its front passes within a diameter of it.
     */
    unsigned int
    cell_category(
      const typename DoFHandler<dim>::active_cell_iterator &cell) const;

    /// Whether the crack front touches @p cell (and it has a special rule).
    bool
    is_tip(const typename DoFHandler<dim>::active_cell_iterator &cell) const;

    /**
     * The quadrature rule of a split or tip cell (reference coordinates), or
     * nullptr for a cell a Gauss rule integrates. Split cells: exact for
     * polynomials of degree 2 @p n_points_1d - 1 on each side of the crack.
     * Tip cells and cells within a diameter of the front: the fan rule with
     * at least `Tip quadrature points` points per direction, or for those
     * of the latter that carry the branch functions alone a Gauss rule
     * (`Near-front quadrature points`, `Near-front quadrature tolerance`).
     * Built on first use and cached until the next set_fe_indices().
     */
    const Quadrature<dim> *
    special_quadrature(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const unsigned int                                    n_points_1d) const;

    /**
     * Whether @p rule, a rule special_quadrature() returned, is one that
     * several cells share (a Gauss rule of the cells near the front): the
     * FEValues of such a rule are worth keeping for the next cell with the
     * same element.
     */
    bool
    is_shared_rule(const Quadrature<dim> *rule) const;

    /**
     * The rule on the lips inside @p cell (reference coordinates, normals
     * pointing to the lsn > 0 lip), empty for a cell that is neither split
     * nor touched by the front: what loads on the lips, the K extraction's
     * lip terms and the error estimator's lip residuals integrate with
     * (CellQuadrature::lip_rule). On the lips of a tip cell the jumps of the
     * branch functions grow like sqrt(r) from the front: Gauss rules need
     * more points there (2 points on sqrt(x) over [0, 1] err by 1 %, 6
     * points by 5e-4), so they get `Tip quadrature points`.
     */
    NonMatching::ImmersedSurfaceQuadrature<dim>
    lip_quadrature(
      const typename DoFHandler<dim>::active_cell_iterator &cell) const;

    /**
     * The rule on the boundary face @p face_no of @p cell (reference
     * coordinates of the cell, weights the face's reference measure): what
     * the K extraction's free-surface term integrates with where a crown
     * crosses the body's boundary (CellQuadrature::boundary_face_rule(),
     * with `Tip quadrature points` where the crack meets the face).
     */
    Quadrature<dim>
    boundary_face_quadrature(
      const typename DoFHandler<dim>::active_cell_iterator &cell,
      const unsigned int                                    face_no) const;

    /// The quadrature of split cells (see special_quadrature()).
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

    /// 0 for a standard DoF, 1 for a Heaviside one, 2 for a branch one.
    static unsigned int
    slot(const FiniteElement<dim> &fe, const unsigned int i);

    /// The gathering part of make_constraints().
    void
    gather_branch_dofs(
      const DoFHandler<dim>                                        &dof_handler,
      const std::vector<std::vector<std::vector<FrontPoint<dim>>>> &fronts,
      AffineConstraints<double> &constraints);

    /// lsn (@p normal) or lst of crack @p c at the vertices of @p cell.
    std::vector<double>
    vertex_values(const typename Triangulation<dim>::cell_iterator &cell,
                  const unsigned int                                c,
                  const bool normal) const;

    /**
     * The shifts of crack @p c's lsn at the vertices of @p cell
     * (fit-to-vertex), and whether any is not zero.
     */
    std::pair<std::array<double, GeometryInfo<dim>::vertices_per_cell>, bool>
    cell_shift(const typename Triangulation<dim>::cell_iterator &cell,
               const unsigned int                                c) const;

    /**
     * The frame (rows e1, e2[, e3]) of crack @p c's level sets at the vertex
     * @p x: e1 along grad lst, e2 along grad lsn made normal to e1, the
     * gradients averaged over the owned and ghost cells of @p cells, the
     * cells around the vertex (GridTools::vertex_to_cell_map(): with the
     * coarser cells a hanging vertex lies on). Smooth along the front and
     * across the tip zone, which is what DOF gathering needs of it.
     */
    Tensor<2, dim>
    vertex_frame(
      const std::set<typename Triangulation<dim>::active_cell_iterator> &cells,
      const unsigned int                                                 c,
      const Point<dim> &x) const;

    /// Decide which vertices crack @p c is fitted to (vertex_shift[c]).
    void
    fit_to_vertices(const Triangulation<dim> &tria, const unsigned int c);

    /// Classification of the cells and vertices by one crack.
    struct CrackZone
    {
      std::vector<CellKind> cell_kind;
      std::vector<double>   fraction_minus;
      std::vector<bool>     near_front;
      std::vector<bool>     heaviside_vertex;
      std::vector<bool>     tip_vertex;
    };

    /// Classify the cells and vertices of @p tria by crack @p c alone.
    CrackZone
    classify(const Triangulation<dim> &tria, const unsigned int c) const;

    const unsigned int         n_cracks;
    const EnrichmentParameters parameters;
    /// Gauss points per direction of the assembly's rules (degree + 1).
    const unsigned int assembly_points_1d;
    /// The cracks' level sets at the vertices ([crack][vertex index]; set
    /// for the vertices of owned and ghost cells), as set_fe_indices() read
    /// them from the fields.
    std::vector<std::vector<double>> vertex_lsn, vertex_lst;
    /// Fit-to-vertex: vertex_shift[crack][vertex] is subtracted from lsn (the
    /// value of lsn at a fitted vertex, 0 elsewhere).
    std::vector<std::vector<double>> vertex_shift;
    /// The level sets and the functions of an enriched cell.
    struct CellFunctions
    {
      CellFunctions(
        const typename Triangulation<dim>::cell_iterator         &cell,
        const std::array<double, CellLevelSets<dim>::n_vertices> &lsn,
        const std::array<double, CellLevelSets<dim>::n_vertices> &lst);
      CellLevelSets<dim>                                level_sets;
      HeavisideFunction<dim>                            heaviside;
      std::vector<std::unique_ptr<BranchFunction<dim>>> branches;
    };
    /// By active cell index: the owned and ghost cells with enriched
    /// functions (null for the others).
    std::vector<std::unique_ptr<CellFunctions>> cell_functions;
    hp::FECollection<dim>                       fe_collection;
    std::vector<CellKind>                       cell_kind;
    /// Gathering (make_constraints()): the tied DoFs and the masters'.
    IndexSet gathered_dofs;
    IndexSet master_dofs;
    /// The crack each cell evaluates (crack_index()).
    std::vector<unsigned char> cell_crack;
    /// Fraction of each cell's volume on the negative side of each crack
    /// ([crack][cell]).
    std::vector<std::vector<double>> fraction_minus;
    /// Cells the front does not touch but passes within a diameter of.
    std::vector<bool> near_front;
    /// Whether the functions of each vertex are enriched by H, by F1..F4
    /// (vertices of the owned and ghost cells).
    std::vector<bool> heaviside_vertex;
    std::vector<bool> tip_vertex;
    /// The rules of special_quadrature(), per cell and order: the cell's
    /// own (cell_rules) or one of the shared Gauss rules (by order).
    mutable std::map<unsigned int, const Quadrature<dim> *> special_rules;
    mutable std::map<unsigned int, Quadrature<dim>>         cell_rules;
    mutable std::map<unsigned int, QGauss<dim>>             gauss_rules;
    /// The tip rules classify() builds to see which side of the crack the
    /// cells' points lie on, by (active cell index, crack):
    /// special_quadrature() takes them over rather than building them again.
    mutable std::map<std::pair<unsigned int, unsigned int>, Quadrature<dim>>
      classified_rules;
  };
} // namespace xcrack

#endif
