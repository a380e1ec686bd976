#ifndef xcrack_elasticity_h
#define xcrack_elasticity_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <deal.II/distributed/tria.h>
#include <deal.II/dofs/dof_handler.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_collection.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/hp/q_collection.h>
#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <xcrack/boundary_conditions.h>
#include <xcrack/crack/crack_set.h>
#include <xcrack/crack/crack_surface.h>
#include <xcrack/crack/level_set_fields.h>
#include <xcrack/fracture/interaction_integral.h>
#include <xcrack/linear_solver.h>
#include <xcrack/material.h>
#include <xcrack/mesh.h>
#include <xcrack/parameters.h>
#include <xcrack/refinement.h>
#include <xcrack/statistics.h>
#include <xcrack/xfem/cell_quadrature.h>
#include <xcrack/xfem/enrichment.h>

#include <memory>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  /**
   * Linear elasticity on a distributed, adaptively refined mesh: the solver
   * every xcrack run is built on (step-8 for the physics, step-40 for the
   * parallel data layout).
   *
   * The finite element space is an hp::FECollection from the start, with a
   * single element for the uncracked body. The X-FEM enrichment adds further
   * elements (Heaviside, tip, both) to this collection and assigns them per
   * cell; assembly, constraints and output already loop over the collection.
   *
   * Construction parses every subsection and builds the mesh; all input
   * errors surface there, as InputError, before run() writes anything.
   */
  template <int dim>
  class ElasticityProblem
  {
  public:
    /// Declare `subsection Discretization` and `Enrichment`.
    static void
    declare_parameters(ParameterHandler &prm);

    ElasticityProblem(ParameterHandler &prm,
                      const MPI_Comm    mpi_communicator = MPI_COMM_WORLD);

    /// Solve on the sequence of meshes and write all results.
    void
    run();

    /// One row per solve, as written to statistics.csv.
    const Statistics &
    get_statistics() const;

  private:
    void
    update_level_sets();

    /// Extract the crack from the level-set fields, report its size,
    /// front and largest opening, and add them to the statistics.
    void
    report_crack_surface();

    void
    setup_system();
    /// Dirichlet constraints, aware of enriched DoFs on the boundary.
    void
    make_dirichlet_constraints();
    void
    assemble_system();

    /**
     * Add the work of the lip pressure in @p cell to @p cell_rhs: the
     * integral over the lips in the cell of p n . [[phi_i]], where n points
     * to the lsn > 0 lip and [[phi_i]] is the jump of the shape function
     * across the crack (only enriched functions jump). The jumps are taken
     * from values a hair's breadth off the crack on each side.
     */
    /// The lip rule of @p cell (empty for a cell without lips).
    NonMatching::ImmersedSurfaceQuadrature<dim>
    lip_rule(const typename DoFHandler<dim>::active_cell_iterator &cell) const;

    /**
     * K and G at the crack tips (InteractionIntegral; 2D only for now):
     * printed, added to the statistics (per tip, and the error against
     * `Reference K`), and written to front_<cycle>.csv.
     */
    void
    compute_fracture_parameters(const unsigned int cycle);

    void
    add_lip_pressure(const typename DoFHandler<dim>::active_cell_iterator &cell,
                     Vector<double> &cell_rhs) const;
    unsigned int
    solve();
    /// Relative L2 and energy-norm errors against the exact solution.
    std::pair<double, double>
    compute_errors() const;
    void
    output_results(const unsigned int cycle);
    void
    print_convergence_table() const;
    /// The largest displacement component at the vertices of the mesh.
    double
    compute_max_displacement() const;
    /// Enriched DoFs that are not constrained, over all ranks.
    types::global_dof_index
    n_free_enriched_dofs() const;

    /**
     * Reinitialise on @p cell and return the FEValues to integrate with:
     * @p hp_fe_values for cells integrated by a Gauss rule, or
     * @p special_values built with the rule Enrichment::special_quadrature()
     * gives for the cells a crack splits or whose front is near (at least
     * @p n_points_1d points per direction).
     */
    const FEValues<dim> &
    reinit_fe_values(const typename DoFHandler<dim>::active_cell_iterator &cell,
                     hp::FEValues<dim>              &hp_fe_values,
                     std::unique_ptr<FEValues<dim>> &special_values,
                     const unsigned int              n_points_1d) const;

    MPI_Comm           mpi_communicator;
    ConditionalOStream pcout;
    /// Created by run(): a timer destroyed while an input error propagates
    /// out of the constructor would print a warning.
    std::unique_ptr<TimerOutput> timer;

    ParameterHandler              &prm;
    RunParameters                  run_parameters;
    Material                       material;
    MeshDescription                mesh_description;
    BoundaryConditions<dim>        boundary_conditions;
    Refinement<dim>                refinement;
    LinearSolver                   linear_solver;
    unsigned int                   degree = 1;
    std::shared_ptr<Function<dim>> exact_solution;
    CrackSet<dim>                  cracks;
    FractureParameters             fracture_parameters;
    /// The X-FEM enrichment, when there is a crack. Declared before the
    /// finite elements and the DoFHandler: they point to its functions.
    std::unique_ptr<Enrichment<dim>> enrichment;

    parallel::distributed::Triangulation<dim> triangulation;
    hp::FECollection<dim>                     fe_collection;
    hp::QCollection<dim>                      quadrature_collection;
    hp::QCollection<dim - 1>                  face_quadrature_collection;
    DoFHandler<dim>                           dof_handler;
    LevelSetFields<dim>                       level_sets;
    /// Each crack as the level-set fields draw it (lips and ordered
    /// fronts).
    std::vector<CrackSurface<dim>> crack_surfaces;

    IndexSet                       locally_owned_dofs;
    IndexSet                       locally_relevant_dofs;
    AffineConstraints<double>      constraints;
    TrilinosWrappers::SparseMatrix system_matrix;
    TrilinosWrappers::MPI::Vector  system_rhs;
    /// Solution with ghost entries, for output, errors and refinement.
    TrilinosWrappers::MPI::Vector solution;

    /// The enriched DoFs (owned and ghost) of the current space.
    IndexSet enriched_dofs;

    Statistics                                  statistics;
    std::vector<std::pair<double, std::string>> pvd_records;
  };
} // namespace xcrack

#endif
