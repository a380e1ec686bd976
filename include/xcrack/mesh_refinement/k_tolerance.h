#ifndef xcrack_mesh_refinement_k_tolerance_h
#define xcrack_mesh_refinement_k_tolerance_h

#include <xcrack/mesh_refinement/interface.h>
#include <xcrack/simulator_access.h>

#include <utility>
#include <vector>

namespace xcrack
{
  namespace MeshRefinement
  {
    /**
     * `k tolerance`: refine (and coarsen) until the estimated error of every
     * K is below a tolerance (`subsection K tolerance`), then stop; in a
     * growth run, every step. This is the one number by which a user trades
     * speed for accuracy: the mesh is as fine as the K's need, where they
     * need it, and no finer.
     *
     * The error and where it sits come from the goal-oriented K error
     * estimate (`Fracture parameters/Error estimate`, KErrorEstimator): the
     * cells' shares of the estimate of K on a wide crown, plus the
     * difference between that K and the reported one shared among the
     * cells of the reported crown, K node by K node and mode by mode, each
     * weighted by its estimate relative to the largest (the goal is the
     * largest). Marking is Doerfler's: the fewest cells
     * that hold `Refine fraction` of the summed shares are refined, those
     * holding `Coarsen fraction` with the smallest shares coarsened (no
     * refinement by the shares once the estimate is below the tolerance
     * and only a crown is too coarse to trust it). Before the run's first
     * solve the crowns around the initial fronts are refined (so that the
     * first estimate can be trusted); after a growth step, before the
     * step's first solve, the mesh is coarsened by the last estimate's
     * shares and the crowns around the moved fronts are refined.
     *
     * Both K's are only as good as the mesh resolves their crowns: the
     * estimate under-reads the error with its crown under 4 cells wide,
     * and a K whose crown spans a few cells of a graded mesh varies by
     * percents (doc/verification.md).
     * So the cells of either crown coarser than its width / `Crown cells`
     * are refined as well, and never coarsened beyond it; and the K's
     * crown must be given as lengths (a crown in cells would shrink with
     * the tip's cells). At the ends of a 3D front on the boundary the
     * reported K with the linear weight falls short of tight tolerances
     * however the mesh is refined (Case 1 in 3D); `Crown weight = smooth`
     * comes closer.
     *
     * The goal: max over tips and modes |K_exact - K|_estimated <=
     * Tolerance * max over tips sqrt(K_I^2 + K_II^2 + K_III^2), with both
     * crowns `Crown cells` wide. Relative to the largest K rather than to each
     * tip's own, so that a tip whose K vanishes (a closed or shielded one)
     * does not ask for endless refinement.
     */
    template <int dim>
    class KTolerance : public Interface<dim>, public SimulatorAccess<dim>
    {
    public:
      static void
      declare_parameters(ParameterHandler &prm);

      void
      parse_parameters(ParameterHandler &prm) override;

      void
      mark(parallel::distributed::Triangulation<dim> &triangulation)
        const override;

      /// Whether its warning was printed (once per run, resumed or not).
      void
      save(Plugins::State &state) const override;

      void
      load(const Plugins::State &state) override;

      bool
      has_goal() const override;

      typename Interface<dim>::GoalStatus
      check_goal() const override;

      /// Its crowns move with the fronts: after a growth step the
      /// Simulator repeats mark() until the crowns around the moved fronts
      /// are fine enough (the first pass also coarsens by the estimate).
      bool
      follows_fronts() const override;

    private:
      /// (inner, outer) radii of the crowns: the K's, and the estimate's
      /// wide one once an estimate ran.
      std::vector<std::pair<double, double>>
      crowns() const;

      /// The largest estimated K error relative to the largest |K|, and
      /// the width of the narrowest crown in its coarsest cells.
      std::pair<double, double>
      distance_to_goal() const;

      /// Says so once per step when the trusted estimates of a step stop
      /// falling: its last three meshes at least doubled the DoFs and the
      /// estimate fell by less than a fifth (Q1's rate in 3D would take
      /// off more than a third).
      void
      check_progress(const double ratio) const;

      double tolerance        = 0.01;
      double refine_fraction  = 0.5;
      double coarsen_fraction = 0.02;
      double crown_cells      = 8;
      /// Whether the warning on geometric tip zones was printed.
      mutable bool warned = false;
      /// This step's trusted meshes: (DoFs, estimated K error / |K|).
      mutable std::vector<std::pair<types::global_dof_index, double>> progress;
      mutable unsigned int progress_step = 0;
      mutable bool         stalled       = false;
    };
  } // namespace MeshRefinement
} // namespace xcrack

#endif
