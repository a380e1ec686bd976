#ifndef xcrack_simulator_h
#define xcrack_simulator_h

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
#include <deal.II/non_matching/immersed_surface_quadrature.h>

#include <xcrack/boundary_conditions.h>
#include <xcrack/crack/crack_set.h>
#include <xcrack/crack/crack_surface.h>
#include <xcrack/crack/level_set_fields.h>
#include <xcrack/fracture/interaction_integral.h>
#include <xcrack/linear_solver.h>
#include <xcrack/material.h>
#include <xcrack/mesh.h>
#include <xcrack/mesh_refinement/interface.h>
#include <xcrack/parameters.h>
#include <xcrack/statistics.h>
#include <xcrack/xfem/enrichment.h>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace xcrack
{
  using namespace dealii;

  template <int dim>
  class SimulatorAccess;

  /**
   * The program: a cracked elastic body on a distributed, adaptively
   * refined mesh, solved on the X-FEM space its cracks enrich (step-8 for
   * the physics, step-40 for the parallel layout, ASPECT for the shape).
   *
   * The Simulator owns the state of a run (mesh, cracks as level-set
   * fields, finite element space, system, solution, fracture parameters,
   * statistics) and the loop over solves; what can be exchanged is a
   * plugin that reads this state through SimulatorAccess. Its member
   * functions live in source/simulator/, one file per phase: parameters
   * and the loop (core.cc), set-up of the space and constraints (setup.cc),
   * assembly (assembly.cc), the solve (solve.cc), errors and the crack's
   * report (postprocess.cc), stress intensity factors (fracture.cc) and
   * output files (output.cc).
   *
   * Construction parses every subsection and builds the mesh; all input
   * errors surface there, as InputError, before run() writes anything.
   */
  template <int dim>
  class Simulator
  {
  public:
    /// Declare the Simulator's own entries and those of its plugin systems.
    static void
    declare_parameters(ParameterHandler &prm);

    Simulator(ParameterHandler &prm,
              const MPI_Comm    mpi_communicator = MPI_COMM_WORLD);

    /// Solve on the sequence of meshes and write all results.
    void
    run();

    /// One row per solve, as written to statistics.csv.
    const Statistics &
    get_statistics() const;

  private:
    friend class SimulatorAccess<dim>;

    /// @name Set-up (setup.cc)
    /// @{
    void
    setup_system();
    void
    update_level_sets();
    /// Dirichlet and pinned-point constraints, aware of enriched DoFs.
    void
    make_dirichlet_constraints();
    /// Enriched DoFs that are not constrained, over all ranks.
    types::global_dof_index
    n_free_enriched_dofs() const;
    /// @}

    /// @name Assembly (assembly.cc)
    /// @{
    void
    assemble_system();

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

    /// The lip rule of @p cell (empty for a cell without lips).
    NonMatching::ImmersedSurfaceQuadrature<dim>
    lip_rule(const typename DoFHandler<dim>::active_cell_iterator &cell) const;

    /**
     * Add the work of the lip pressure in @p cell to @p cell_rhs: the
     * integral over the lips in the cell of p n . [[phi_i]], where n points
     * to the lsn > 0 lip and [[phi_i]] is the jump of the shape function
     * across the crack (only enriched functions jump). The jumps are taken
     * from values a hair's breadth off the crack on each side.
     */
    void
    add_lip_pressure(const typename DoFHandler<dim>::active_cell_iterator &cell,
                     Vector<double> &cell_rhs) const;
    /// @}

    /**
     * Refine the mesh by the strategy plugin, capped at `Maximum level`
     * (refinement.cc).
     */
    void
    refine_mesh();

    /// Solve the system and distribute the constraints (solve.cc).
    unsigned int
    solve();

    /// @name Postprocessing (postprocess.cc)
    /// @{
    /// Relative L2 and energy-norm errors against the exact solution.
    std::pair<double, double>
    compute_errors() const;
    /// The largest displacement component at the vertices of the mesh.
    double
    compute_max_displacement() const;
    /// Extract the crack from the level-set fields, report its size,
    /// front and largest opening, and add them to the statistics.
    void
    report_crack_surface();
    void
    print_convergence_table() const;
    /// @}

    /**
     * K and G along the fronts (InteractionIntegral), cross-checked by the
     * displacement jumps: printed, added to the statistics (and the error
     * against `Reference K`), written to front_<cycle>.csv (fracture.cc).
     */
    void
    compute_fracture_parameters(const unsigned int cycle);

    /// VTU files of the solution and of the cracks (output.cc).
    void
    output_results(const unsigned int cycle);

    MPI_Comm           mpi_communicator;
    ConditionalOStream pcout;
    /// Created by run(): a timer destroyed while an input error propagates
    /// out of the constructor would print a warning.
    std::unique_ptr<TimerOutput> timer;

    ParameterHandler                               &prm;
    RunParameters                                   run_parameters;
    FunctionConstants                               function_constants;
    Material                                        material;
    MeshDescription                                 mesh_description;
    BoundaryConditions<dim>                         boundary_conditions;
    LinearSolver                                    linear_solver;
    unsigned int                                    degree = 1;
    std::shared_ptr<Function<dim>>                  exact_solution;
    CrackSet<dim>                                   cracks;
    FractureParameters                              fracture_parameters;
    MeshRefinement::Parameters                      refinement_parameters;
    std::unique_ptr<MeshRefinement::Interface<dim>> mesh_refinement;
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
