#ifndef xcrack_simulator_h
#define xcrack_simulator_h

#include <deal.II/base/bounding_box.h>
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
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/non_matching/immersed_surface_quadrature.h>

#include <xcrack/assembly/interface.h>
#include <xcrack/boundary_conditions.h>
#include <xcrack/contact/interface.h>
#include <xcrack/crack/crack_set.h>
#include <xcrack/crack/crack_surface.h>
#include <xcrack/crack/level_set_fields.h>
#include <xcrack/directory_lock.h>
#include <xcrack/fracture/interaction_integral.h>
#include <xcrack/fracture/k_error_estimator.h>
#include <xcrack/front_move.h>
#include <xcrack/linear_solver/interface.h>
#include <xcrack/load_cycle.h>
#include <xcrack/material.h>
#include <xcrack/mesh.h>
#include <xcrack/mesh_refinement/interface.h>
#include <xcrack/nonlinear_solver.h>
#include <xcrack/parameters.h>
#include <xcrack/propagation.h>
#include <xcrack/run_record.h>
#include <xcrack/statistics.h>
#include <xcrack/termination_criteria/interface.h>
#include <xcrack/work_balance.h>
#include <xcrack/xfem/enrichment.h>

#include <chrono>
#include <map>
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
   * the growth of the cracks, statistics) and the loop over solves; what
   * can be exchanged is a plugin that reads this state through
   * SimulatorAccess. Its member functions live in source/simulator/, one
   * file per phase: parameters and the loop (core.cc), set-up of the space
   * and constraints (setup.cc), assembly (assembly.cc), the solve
   * (solve.cc), errors and the crack's report (postprocess.cc), stress
   * intensity factors (fracture.cc), the growth of the cracks (growth.cc),
   * mesh refinement (refinement.cc), output files (output.cc) and
   * checkpoints (checkpoint.cc).
   *
   * Words: a *step* is one propagation step of the cracks (step 0 is the
   * initial crack, which may be solved on several successively refined
   * meshes, `Mesh refinement/Number of meshes`); *cycles* are load cycles
   * N.
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

    /**
     * Parse and check every input and build the mesh. With a non-empty
     * @p resume_directory, run() continues the run checkpointed there
     * instead of starting one (`xcrack --resume`). With @p check_only
     * (`xcrack --check`) the checks create nothing: a missing output
     * directory is not made.
     */
    Simulator(ParameterHandler  &prm,
              const MPI_Comm     mpi_communicator = MPI_COMM_WORLD,
              const std::string &resume_directory = "",
              const bool         check_only       = false);

    /// Solve on the sequence of meshes and steps and write all results,
    /// with their record run.json.
    void
    run();

    /// The entries the command line set (`xcrack -s`), for run.json.
    void
    record_overrides(const std::vector<std::string> &overrides);

    /// One row per solve, as written to statistics.csv.
    const Statistics &
    get_statistics() const;

  private:
    friend class SimulatorAccess<dim>;

    /// The loop of run(): the steps and their meshes (core.cc).
    void
    run_steps();

    /// @name Checks of the input that need the mesh (input_checks.cc)
    /// @{
    /**
     * The loads of both load states must be finite where they are used and
     * hold the body (setting displacement_scale: how far they can move
     * it), and a lip pressure needs a crack.
     */
    void
    check_loads();
    /// Each crack must be one the mesh sees (a cell cut along it).
    void
    check_cracks_seen();
    /// The crowns must be smaller than the body (Fracture parameters/Crown
    /// radii).
    void
    check_crowns();
    /// The bounding box of the body (collective).
    BoundingBox<dim>
    body_box() const;
    /// The output directory must be one the run can write into.
    void
    check_output_directory();
    /// @}

    /// @name Set-up (setup.cc)
    /// @{
    /// The enrichment (with cracks), the finite elements and their rules.
    void
    create_finite_elements(ParameterHandler &prm);
    /// How the lips touch (`subsection Contact`), the contributions to the
    /// system, and whether the linear solver can solve it.
    void
    create_terms(ParameterHandler &prm);
    /**
     * The cracks' fields, the enrichment, the DoFs, the constraints and
     * the system on the current mesh. With @p may_split, the mesh may
     * first be split again among the ranks by the work of its cells
     * (share_work()); a caller that keeps vectors of the current split
     * across the call passes false.
     */
    void
    setup_system(const bool may_split = true);
    /**
     * On several ranks, once the enrichment has classified the cells:
     * split the mesh again by their work if WorkBalance asks for it (and
     * @p may_split), classify again, and keep the imbalance left for the
     * statistics.
     */
    void
    share_work(const bool may_split);
    void
    update_level_sets();
    /**
     * The work of each locally owned cell in the assembly and the K
     * extraction, by active cell index: quadrature points times DoFs
     * (WorkBalance).
     */
    std::vector<unsigned int>
    cell_work() const;
    /**
     * The constraints of the space with the Dirichlet data of @p state:
     * hanging nodes, the enrichment's (gathering along the fronts of
     * gathering_fronts), Dirichlet and pinned points.
     */
    void
    make_constraints(const LoadState<dim> &state);
    /// Dirichlet and pinned-point constraints of @p state, aware of
    /// enriched DoFs.
    void
    make_dirichlet_constraints(const LoadState<dim> &state);
    /// Enriched DoFs that are not constrained, over all ranks.
    types::global_dof_index
    n_free_enriched_dofs() const;
    /**
     * The contributions' own unknowns (Lagrange multipliers) on the current
     * space: set up, their offsets after the DoFs, and the system's owned
     * rows (the owned DoFs alone without any).
     */
    void
    setup_own_unknowns();
    /**
     * The system's matrix, right-hand side and solution with own unknowns:
     * @p dsp, the DoFs' pattern on @p dof_rows, extended by the couplings of
     * the cells' own unknowns.
     */
    void
    setup_system_with_own_unknowns(const DynamicSparsityPattern &dsp,
                                   const IndexSet               &dof_rows);
    /// The constraints the assembly condenses with (those of the DoFs, on
    /// the system's index range when there are own unknowns).
    const AffineConstraints<double> &
    assembly_constraints() const;
    /// @}

    /// @name Assembly (assembly.cc)
    /// @{
    /**
     * The system of @p state linearised at the current iterate (the
     * solution; zero if @p first): the sum of the contributions'
     * (Assembly::Contribution), condensed by the constraints.
     */
    void
    assemble_system(const LoadState<dim> &state, const bool first);

    /// The contributions of the scene's terms to the system: the bulk's,
    /// the loads', and contact on the lips if the lips touch.
    void
    create_contributions();

    /// What the system's matrix is (symmetric positive definite unless a
    /// contribution makes it otherwise).
    LinearSolver::MatrixProperty
    matrix_property() const;

    /**
     * The FEValues of the cells with rules of their own
     * (reinit_fe_values()): one rebuilt for each cell whose rule is its
     * own, and one kept per element and shared rule
     * (Enrichment::is_shared_rule(): the Gauss rules of the cells near the
     * front), whose construction would otherwise cost as much as their
     * integration.
     */
    struct SpecialFEValues
    {
      std::unique_ptr<FEValues<dim>> per_cell;
      std::map<std::pair<const Quadrature<dim> *, unsigned int>,
               std::unique_ptr<FEValues<dim>>>
        shared;
    };

    /**
     * Reinitialise on @p cell and return the FEValues to integrate with:
     * @p hp_fe_values for cells integrated by a Gauss rule, or one of
     * @p special_values built with the rule Enrichment::special_quadrature()
     * gives for the cells a crack splits or whose front is near (at least
     * @p n_points_1d points per direction).
     */
    const FEValues<dim> &
    reinit_fe_values(const typename DoFHandler<dim>::active_cell_iterator &cell,
                     hp::FEValues<dim> &hp_fe_values,
                     SpecialFEValues   &special_values,
                     const unsigned int n_points_1d) const;

    /// @}

    /// @name The solve (solve.cc)
    /// @{
    /// Solve the assembled system for the solution and distribute the
    /// constraints; returns the linear solver's iterations.
    unsigned int
    solve();

    /// (|b - A u|, |b|) of the assembled system at the solution, over the
    /// unknowns that are not constrained.
    std::pair<double, double>
    residual_norms() const;

    /**
     * Solve @p state by the nonlinear driver (a linear scene: one assembly
     * and one solve) on the current space, whose system must be set up;
     * returns what the driver did.
     */
    NonlinearSolver::Result
    solve_load_state(const LoadState<dim> &state);

    /// Whether every contribution is linear (no contact): one solve per
    /// load state, and K proportional to the loads.
    bool
    is_linear() const;

    /// Whether a growth step solves the minimum of the load cycle (rather
    /// than scale the maximum's K's by the load ratio).
    bool
    solves_minimum() const;

    /**
     * K at the points of front_values under the minimum of the load cycle:
     * the maximum's times the load ratio, or (solves_minimum()) solved and
     * extracted on the current space, after which the solution and the
     * constraints are the maximum's again.
     */
    std::vector<FrontValues<dim>>
    minimum_front_values();
    /// @}

    /**
     * Set up, assemble and solve on the current mesh, start the statistics
     * row of this solve (@p mesh of @p n_meshes of the current step) and
     * report the crack and its K (core.cc).
     */
    void
    solve_and_report(const unsigned int mesh, const unsigned int n_meshes);

    /// The most meshes step @p step_of_solve is solved on (core.cc).
    unsigned int
    n_meshes_of(const unsigned int step_of_solve) const;

    /**
     * The name of the files of the solve on mesh @p mesh of step
     * @p step_of_solve: the step (`007`), or the step and the mesh
     * (`000.03`) when the step is solved on several meshes.
     */
    std::string
    solve_key(const unsigned int step_of_solve, const unsigned int mesh) const;

    /// The timings of the solve into its row, the output files under the
    /// name @p key and statistics.csv (core.cc).
    void
    finish_solve(const std::string &key);

    /// @name Growth (growth.cc)
    /// @{
    /**
     * After the solve of a growth step: the moves of the front points, the
     * cycles since the last step, the termination criteria, the advance of
     * the next step; returns whether the run stops here.
     */
    bool
    grow();

    /// Move the cracks' fields by the moves, adapt the mesh to the new
    /// fronts and write a checkpoint.
    void
    advance_cracks();

    /**
     * Direction integration = predictor-corrector: move the cracks by the
     * moves on the current mesh, solve, extract K there, correct the moves'
     * kinks by the trial fronts' (Propagation::correct_directions()), undo
     * the trial and rewrite the front file @p key with the corrected moves.
     */
    void
    correct_directions(const std::string &key);

    /// The fronts per crack, as compute_fracture_parameters() numbers them.
    std::vector<unsigned int>
    fronts_per_crack() const;

    /**
     * One step: its solves (several meshes at step 0 or with a goal), the
     * moves, the files of its last solve (@p key), and the advance to the
     * next step. Whether the run stops.
     */
    bool
    run_step(std::string &key);

    /// Whether the run stops after this step's solve, and why; else
    /// @p largest (the nominal advance on entry) as the criteria limit it.
    TerminationCriteria::Verdict
    step_verdict(double &largest) const;

    /// The step's line on screen, its warnings and statistics, and the end
    /// of the run if @p verdict says so.
    void
    report_step(const TerminationCriteria::Verdict &verdict,
                const double                        delta_cycles,
                const double                        largest);

    /// The cycles so far that rest on a flagged K (unreliable_cycles):
    /// those of the last advance, @p delta_cycles, if a point of this step
    /// or the previous one is flagged.
    void
    count_unreliable_cycles(const double delta_cycles);

    /// A stop if a crack has fewer fronts than at the last step (a tip ran
    /// out of the body): grow() then counts no cycles for the advance.
    TerminationCriteria::Verdict
    check_vanished_fronts() const;

    /// A failure if the growth law gives a rate that is not finite at a
    /// point of front_moves (Forman at K_Ic, a power that overflows).
    TerminationCriteria::Verdict
    check_rates() const;
    /// @}

    /// @name Checkpoints (checkpoint.cc)
    /// @{
    /// Write the state of the run atomically (collective).
    void
    write_checkpoint();

    /// Restore the state written by write_checkpoint() from the
    /// checkpoint of @p directory.
    void
    read_checkpoint(const std::string &directory);

    /// Replace the mesh and the cracks' fields by those of the checkpoint
    /// directory @p checkpoint.
    void
    load_mesh(const std::string &checkpoint);

    /**
     * Every plugin of the run, keyed by its system and name ("Termination
     * criteria/crack size"): the checkpoint saves and loads their states
     * under these keys.
     */
    std::map<std::string, Plugins::InterfaceBase *>
    plugins() const;
    /// @}

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
     * K and G along the fronts (InteractionIntegral) under @p state (its
     * lip pressure and body force enter the integrals) into front_values,
     * cross-checked by the displacement jumps: printed, added to the
     * statistics (and the error against `Reference K`) (fracture.cc). With
     * @p report false only front_values (a trial step's).
     */
    void
    compute_fracture_parameters(const LoadState<dim> &state,
                                const bool            report = true);

    /// The number of front points whose K cannot be trusted, and why, into
    /// the statistics row (the front file says which) (fracture.cc).
    void
    flag_unreliable_points();

    /**
     * What the run's results rest on, at its end: the solves whose front
     * points are flagged, and in a growth run the cycles that rest on
     * their K. On screen and in run.json (growth.cc).
     */
    void
    report_unreliable();

    /// (r_inf, r_sup) of the estimate's wide crown around @p fronts (2D:
    /// a point each): as wide as the boundary, the other fronts and, in
    /// 3D, the fronts' curvature allow (fracture.cc).
    std::pair<double, double>
    wide_crown(const std::vector<std::vector<FrontPoint<dim>>> &fronts) const;

    /// Place k_error_cells' wide crown around @p fronts not solved on yet
    /// (the initial or the moved ones), never narrower than the K's crown
    /// given as lengths, for a strategy that refines it before the solve
    /// (k tolerance) (fracture.cc).
    void
    expect_wide_crown(const std::vector<std::vector<FrontPoint<dim>>> &fronts);

    /**
     * What the boundary faces of the body carry under @p state, for the
     * crowns that cross them (InteractionIntegral::BoundaryFace): a
     * Dirichlet condition, or the scaled Neumann traction and the face's
     * X-FEM rule. The returned function refers to @p state.
     */
    typename InteractionIntegral<dim>::BoundaryFaceOf
    boundary_face_of(const LoadState<dim> &state) const;

    /**
     * The estimates of the error of the K's in front_values: K on a wide
     * crown (as wide as the boundary and the other tips allow, for a dual
     * problem the mesh resolves), the estimate of its error
     * (KErrorEstimator, a dual solve per K mode and test function of the
     * front; along a 3D front the wide crown's K on the reported nodes),
     * and the difference of the two K's. The wide crown crosses the body's
     * faces as the reported K's does (@p faces, boundary_face_of()).
     */
    void
    estimate_k_errors(
      const std::vector<std::vector<FrontPoint<dim>>>         &fronts,
      const typename InteractionIntegral<dim>::FEValuesOf     &fe_values_of,
      const typename InteractionIntegral<dim>::LipsOf         &lips_of,
      const typename InteractionIntegral<dim>::BoundaryFaceOf &faces);

    /// front_<key>.csv: K, G and, in a growth run, the moves (fracture.cc).
    void
    write_front_file(const std::string &key) const;

    /// The table of write_front_file() into @p csv.
    void
    write_front_table(std::ostream &csv) const;

    /**
     * Add the files of this solve to a ParaView series (solution.pvd,
     * crack.pvd): at the time of the solve, the load cycles (a growth run),
     * the step (one that counts no cycles) or the mesh (a static run),
     * replacing an earlier solve of the same step (output.cc).
     */
    void
    add_series_record(std::vector<std::pair<double, std::string>> &records,
                      const std::vector<std::string>              &files) const;

    /// A PVD file of @p records, @p n_parts files at each time (output.cc).
    static void
    write_series(std::ostream                                      &pvd,
                 const std::vector<std::pair<double, std::string>> &records,
                 const unsigned int                                 n_parts);

    /// VTU files of the solution and of the cracks (output.cc).
    void
    output_results(const std::string &key);

    /**
     * Refine the mesh by the strategy plugin, capped at `Maximum level`,
     * the cracks' fields carried across (refinement.cc); false if the mesh
     * did not change.
     */
    bool
    refine_mesh();

    /**
     * After the cracks moved: refine (and coarsen) with a strategy that
     * follows the fronts until it marks nothing; other strategies leave
     * the mesh as it is (refinement.cc).
     */
    void
    adapt_mesh_to_fronts();

    /**
     * Before the first solve of a fresh run with a strategy that has a
     * goal: refine what the strategy knows it needs before any solve (k
     * tolerance: its crowns, the estimate's wide one around the initial
     * fronts included), as before each growth step's solve, so that no
     * solve is spent on a mesh the goal would not trust (refinement.cc).
     */
    void
    refine_before_first_solve();

    /// Execute the marked refinement and coarsening, capped at the levels
    /// of the parameters (and at @p level_cap), carrying the fields; false
    /// if nothing was marked, or if only coarsening was and the mesh kept
    /// every cell (it did not change).
    bool
    execute_refinement(
      const unsigned int level_cap = numbers::invalid_unsigned_int);

    /// Clear the flags beyond the levels of the parameters (and refine
    /// flags at @p level_cap); false if no flag is left on any rank.
    bool
    cap_refinement_flags(
      const unsigned int level_cap = numbers::invalid_unsigned_int);

    /**
     * After a solve, for a strategy with a goal: report how far the goal
     * is and, unless it is met or this is the @p last_mesh allowed, mark
     * the cells for the next mesh. Returns whether this mesh is the last
     * of the step (goal met, no mesh left, or nothing left to refine).
     */
    bool
    check_mesh_goal(const bool last_mesh);

    MPI_Comm           mpi_communicator;
    ConditionalOStream pcout;
    /// Created by run(): a timer destroyed while an input error propagates
    /// out of the constructor would print a warning.
    std::unique_ptr<TimerOutput> timer;

    ParameterHandler &prm;
    /// Every parameter of the run (ShortPRM), printed once by run_steps():
    /// parameters.prm and each checkpoint's copy.
    std::string parameters_text;
    /// The lock on the output directory, held for the run (rank 0).
    std::unique_ptr<DirectoryLock> output_lock;
    /// Whether a solve's files were written (or the run resumed): an
    /// input check that fails after that ends the run instead.
    bool                    results_written = false;
    RunParameters           run_parameters;
    FunctionConstants       function_constants;
    Material                material;
    MeshDescription         mesh_description;
    BoundaryConditions<dim> boundary_conditions;
    /// The solver of the linear systems, and its name (`Linear
    /// solver/Type`).
    std::unique_ptr<LinearSolver::Interface<dim>> linear_solver;
    std::string                                   linear_solver_type;
    NonlinearSolver                               nonlinear_solver;
    /// The maximum (the loads of the file) and the minimum of the load
    /// cycle.
    LoadCycle<dim>                 load_cycle;
    WorkBalance<dim>               work_balance;
    unsigned int                   degree = 1;
    std::shared_ptr<Function<dim>> exact_solution;
    CrackSet<dim>                  cracks;
    FractureParameters             fracture_parameters;
    Propagation<dim>               propagation;
    std::vector<std::unique_ptr<TerminationCriteria::Interface<dim>>>
                                                    termination_criteria;
    MeshRefinement::Parameters                      refinement_parameters;
    std::unique_ptr<MeshRefinement::Interface<dim>> mesh_refinement;
    /// The X-FEM enrichment, when there is a crack. Declared before the
    /// finite elements and the DoFHandler: they point to its functions.
    std::unique_ptr<Enrichment<dim>> enrichment;

    parallel::distributed::Triangulation<dim> triangulation;
    hp::FECollection<dim>                     fe_collection;
    hp::QCollection<dim>                      quadrature_collection;
    hp::QCollection<dim - 1>                  face_quadrature_collection;
    /// How the crack lips touch (null: they do not).
    std::unique_ptr<Contact::Interface<dim>> contact;
    /// The terms of the weak form, each adding to the system: those owned
    /// here (the bulk's, the loads'), and all of them, contact included.
    std::vector<std::unique_ptr<Assembly::Contribution<dim>>> own_terms;
    std::vector<Assembly::Contribution<dim> *>                contributions;
    DoFHandler<dim>                                           dof_handler;
    LevelSetFields<dim>                                       level_sets;
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

    /// @name Unknowns of the contributions' own (Lagrange multipliers)
    /// @{
    /// The system's unknowns are the DoFs, then those of each contribution
    /// (at n_dofs + own_offsets[c]); without any, the DoFs alone.
    std::vector<types::global_dof_index> own_offsets;
    types::global_dof_index              n_own_unknowns = 0;
    /// The system's locally owned rows (the owned DoFs and own unknowns).
    IndexSet system_owned;
    /// The constraints on the system's index range (those of the DoFs),
    /// for its assembly; only with own unknowns.
    AffineConstraints<double> system_constraints;
    /// The last solve's unknowns, DoFs and own alike (owned entries).
    TrilinosWrappers::MPI::Vector system_solution;
    /// @}

    /// The enriched DoFs (owned and ghost) of the current space.
    IndexSet enriched_dofs;
    /// With DOF gathering: the fronts of each crack the branch DoFs are
    /// gathered along (the constraints of every load state tie them).
    std::vector<std::vector<std::vector<FrontPoint<dim>>>> gathering_fronts;
    /// The largest rank's work over the mean (WorkBalance::imbalance()) of
    /// the current space; 1 on one rank.
    double work_imbalance = 1;

    /// @name The state of a growth run (checkpointed)
    /// @{
    /// The propagation step and the load cycles of the current solve.
    unsigned int step   = 0;
    double       cycles = 0;
    /// Whether the cracks left their initial shapes: until then each new
    /// mesh interpolates the shapes, afterwards the fields are carried.
    bool cracks_moved = false;
    /// The moves of the previous step (for the cycle integration; empty
    /// before the first one).
    std::vector<FrontMove<dim>> previous_moves;
    Statistics                  statistics;
    /// (time, file) of the series solution.pvd and crack.pvd
    /// (add_series_record()).
    std::vector<std::pair<double, std::string>> pvd_records, crack_records;
    /// @}

    /// K at the points of every front (fronts numbered crack after crack)
    /// and, in a growth run, their moves: the state of the current step.
    std::vector<FrontValues<dim>> front_values;
    /// Where the K error estimate sits (its indicators are emptied when
    /// the mesh changes).
    KErrorCells                 k_error_cells;
    std::vector<FrontMove<dim>> front_moves;

    /// How far the loads can move the body, in order of magnitude
    /// (BoundaryConditions::check_finite()).
    double displacement_scale = 0;

    /// run.json (created by run()).
    std::unique_ptr<RunRecord> run_record;
    /// Why the run ended (a termination criterion), for run.json.
    std::string end_reason;

    /// The checkpoint to continue from (empty: a new run).
    std::string resume_directory;
    /// Only the input checks (`xcrack --check`): nothing is created.
    bool check_only = false;
    /// The level of the cells at the fronts during growth, once step 0 set
    /// it (adapt_mesh_to_fronts()).
    unsigned int growth_front_level = numbers::invalid_unsigned_int;
    /// The entries the command line set (run.json lists them).
    std::vector<std::string> command_line_overrides;
    /// Whether the screen shows the detail of each solve (the crack, K per
    /// tip or front) or one line per step.
    bool detailed_screen = true;
    /// Wall time of each phase up to the last row (for the per-row times).
    std::map<std::string, double> previous_times;
    /// When run() started (for the estimate of the remaining time).
    std::chrono::steady_clock::time_point start_time;
  };
} // namespace xcrack

#endif
