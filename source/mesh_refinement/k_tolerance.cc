#include <deal.II/distributed/grid_refinement.h>

#include <xcrack/crack/crack_set.h>
#include <xcrack/crack/level_set_fields.h>
#include <xcrack/fracture/interaction_integral.h>
#include <xcrack/input_error.h>
#include <xcrack/mesh_refinement/k_tolerance.h>
#include <xcrack/xfem/enrichment.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace xcrack
{
  namespace MeshRefinement
  {
    template <int dim>
    void
    KTolerance<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("K tolerance");
      {
        prm.declare_entry(
          "Tolerance",
          "0.01",
          Patterns::Double(0),
          "The goal: the estimated error of every K, relative to the "
          "largest |K| = sqrt(K_I^2 + K_II^2 + K_III^2) over the tips (the "
          "front's K nodes in 3D), at most this. Needs Fracture "
          "parameters/Error estimate = true.");
        prm.declare_entry("Refine fraction",
                          "0.5",
                          Patterns::Double(0, 1),
                          "Refine the fewest cells that hold this fraction "
                          "of the estimated K error.");
        prm.declare_entry("Coarsen fraction",
                          "0.02",
                          Patterns::Double(0, 1),
                          "Coarsen the cells with the smallest shares of the "
                          "estimated K error that hold this fraction of it.");
        prm.declare_entry(
          "Crown cells",
          "8",
          Patterns::Double(4),
          "The goal is trusted once each crown (the K's and the wider one "
          "of the estimate's dual problems) spans this many of its coarsest "
          "cells; coarser cells there are refined too. More costs cells "
          "away from the tip and makes the estimate more accurate (16: 1.1 "
          "to 3.5 times the cells on the 2D benchmarks; "
          "doc/verification.md).");
      }
      prm.leave_subsection();
    }



    template <int dim>
    void
    KTolerance<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "K tolerance");
      tolerance                  = prm.get_double("Tolerance");
      refine_fraction            = prm.get_double("Refine fraction");
      coarsen_fraction           = prm.get_double("Coarsen fraction");
      crown_cells                = prm.get_double("Crown cells");
      const std::string strategy = "Mesh refinement/Strategy = k tolerance";
      check_input(tolerance > 0,
                  "Mesh refinement/K tolerance/Tolerance must be positive.");
      check_input(refine_fraction > 0 &&
                    refine_fraction + coarsen_fraction <= 1,
                  "Mesh refinement/K tolerance/Refine fraction must be "
                  "positive, and Refine fraction + Coarsen fraction must "
                  "not exceed 1.");
      check_input(this->get_initial_cracks().size() > 0,
                  strategy + " needs a crack (Cracks/Number of cracks = 0).");
      const FractureParameters &fracture = this->get_fracture_parameters();
      check_input(fracture.compute && fracture.error_estimate,
                  strategy +
                    " refines by the estimated K errors: set Fracture "
                    "parameters/Compute = true and Error estimate = true.");
      check_input(!fracture.crown_in_cells,
                  strategy +
                    " with Fracture parameters/Crown unit = cells: the "
                    "crown would shrink with the tip's cells as they are "
                    "refined, and its K on a graded mesh varies by percents "
                    "(doc/verification.md); set Crown unit = absolute and "
                    "Crown radii as lengths.");
    }



    template <int dim>
    bool
    KTolerance<dim>::has_goal() const
    {
      return true;
    }



    template <int dim>
    std::vector<std::pair<double, double>>
    KTolerance<dim>::crowns() const
    {
      const KErrorCells        &estimate = this->get_k_error_cells();
      const FractureParameters &fracture = this->get_fracture_parameters();
      std::vector<std::pair<double, double>> radii = {
        {fracture.crown_inner, fracture.crown_outer}};
      // (None before the run's first estimate; a checkpoint keeps it.)
      if (estimate.crown_outer > 0)
        radii.emplace_back(estimate.crown_inner, estimate.crown_outer);
      return radii;
    }



    template <int dim>
    std::pair<double, double>
    KTolerance<dim>::distance_to_goal() const
    {
      const auto &values = this->get_front_values();
      double      k_max = 0, error_max = 0;
      for (const FrontValues<dim> &v : values)
        {
          k_max = std::max(k_max, std::hypot(v.k_I, v.k_II, v.k_III));
          for (unsigned int m = 0; m < dim; ++m)
            error_max = std::max(error_max, std::abs(v.k_error[m]));
        }
      const double ratio =
        (k_max > 0 ? error_max / k_max : std::numeric_limits<double>::max());
      // Each crown's width in its coarsest cells (the distances those of
      // mark(), so that what this measures, mark() refines).
      const std::vector<double> distances =
        this->get_level_set_fields().cell_front_distances();
      double crown = std::numeric_limits<double>::max();
      for (const auto &[inner, outer] : crowns())
        {
          double h = 0;
          for (const auto &cell :
               this->get_triangulation().active_cell_iterators())
            if (cell->is_locally_owned())
              {
                const double r    = distances[cell->active_cell_index()];
                const double half = cell->diameter() / 2;
                if (r + half > inner && r - half < outer)
                  h = std::max(h, cell->diameter() / std::sqrt(double(dim)));
              }
          h = Utilities::MPI::max(h, this->get_mpi_communicator());
          if (h > 0)
            crown = std::min(crown, (outer - inner) / h);
        }
      return {ratio, crown};
    }



    template <int dim>
    typename Interface<dim>::GoalStatus
    KTolerance<dim>::check_goal() const
    {
      // A crack without a front (it runs through the body) has no K.
      if (this->get_front_values().empty())
        return {true, "no crack front, no K to refine for"};
      const auto [ratio, crown]   = distance_to_goal();
      const bool         reliable = (crown >= crown_cells);
      std::ostringstream text;
      text << "largest estimated K error " << std::setprecision(3)
           << 100 * ratio << " % of the largest |K| (tolerance "
           << 100 * tolerance << " %)";
      if (!reliable)
        text << ", not trusted yet (a crown spans " << std::setprecision(2)
             << crown << " of its cells, " << crown_cells << " asked)";
      const bool met = reliable && ratio <= tolerance;
      text << (met ? ": met" : ": refining");
      if (reliable && !met)
        check_progress(ratio);
      return {met, text.str()};
    }



    template <int dim>
    void
    KTolerance<dim>::check_progress(const double ratio) const
    {
      if (progress_step != this->get_step())
        {
          progress.clear();
          progress_step = this->get_step();
          stalled       = false;
        }
      progress.emplace_back(this->get_dof_handler().n_dofs(), ratio);
      if (stalled || progress.size() < 3)
        return;
      const auto [dofs_before, ratio_before] = progress[progress.size() - 3];
      if (progress.back().first < 2 * dofs_before ||
          ratio <= 0.8 * ratio_before)
        return;
      stalled = true;
      std::ostringstream text;
      text << "  Warning: the estimated K error went from "
           << std::setprecision(3) << 100 * ratio_before << " % to "
           << 100 * ratio << " % of the largest |K| while the DoFs grew from "
           << dofs_before << " to " << progress.back().first
           << ": the refinement does not lower it"
           << (this->get_fracture_parameters().smooth_weight ?
                 "" :
                 "; where the largest error sits at the ends of a front on "
                 "the boundary, Fracture parameters/Crown weight = smooth "
                 "did better")
           << " (doc/verification.md, \"Along a 3D front\").";
      this->get_pcout() << text.str() << std::endl;
    }



    template <int dim>
    void
    KTolerance<dim>::mark(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      // A solve that found no front (the crack runs through the body) has
      // no K to refine for. Before the first solve neither is known, and
      // the crowns around the fronts the fields draw are refined.
      if (this->get_front_values().empty() &&
          !this->get_crack_surfaces().empty())
        return;
      if (!warned && this->get_enrichment()->get_parameters().tip_zone ==
                       EnrichmentParameters::TipZone::geometric)
        {
          this->get_pcout()
            << "  Warning: Mesh refinement/Strategy = k tolerance with "
               "Enrichment/Tip enrichment = geometric: every refinement "
               "inside the enrichment radius adds branch DoFs (and "
               "conditioning), where topological enrichment keeps their "
               "number as the mesh is refined (doc/verification.md, "
               "\"Refining to a K tolerance\")."
            << std::endl;
          warned = true;
        }
      // The estimate's shares, if it ran on this mesh (not after a first
      // refinement, nor before the first solve of a resumed run): refine
      // the cells holding Refine fraction of the error, unless the
      // estimate is below the tolerance already (and only a crown is too
      // coarse to trust it), and coarsen those holding Coarsen fraction.
      const KErrorCells &estimate = this->get_k_error_cells();
      if (estimate.indicators.size() == triangulation.n_active_cells())
        {
          const double ratio = distance_to_goal().first;
          parallel::distributed::GridRefinement::
            refine_and_coarsen_fixed_fraction(triangulation,
                                              estimate.indicators,
                                              ratio <= tolerance ?
                                                0. :
                                                refine_fraction,
                                              coarsen_fraction,
                                              VectorTools::L1_norm);
        }

      // The cells of the crowns around the fronts the fields draw now (in
      // a growth run, the moved ones): at most a crown's width / Crown
      // cells across, and no coarsening that makes a parent (twice the
      // size, its centre up to half a diameter away) meet a crown coarser
      // than that.
      const std::vector<double> distances =
        this->get_level_set_fields().cell_front_distances();
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const auto &[inner, outer] : crowns())
            {
              const double r        = distances[cell->active_cell_index()];
              const double diameter = cell->diameter();
              const auto   meets    = [&](const double half) {
                return r + half > inner && r - half < outer;
              };
              const double h     = diameter / std::sqrt(double(dim));
              const double h_max = (outer - inner) / crown_cells;
              if (2 * h > h_max && meets(1.5 * diameter))
                cell->clear_coarsen_flag();
              if (h > h_max && meets(diameter / 2))
                cell->set_refine_flag();
            }
    }



    template <int dim>
    bool
    KTolerance<dim>::follows_fronts() const
    {
      return true;
    }

    template <int dim>
    void
    KTolerance<dim>::save(Plugins::State &state) const
    {
      state["warned"] = Plugins::pack(warned);
    }



    template <int dim>
    void
    KTolerance<dim>::load(const Plugins::State &state)
    {
      warned = Plugins::unpack(state, "warned", warned);
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           KTolerance,
                           "k tolerance",
                           "refine (and coarsen) until the estimated error "
                           "of every K is below a tolerance, every step "
                           "(subsection K tolerance).")
  } // namespace MeshRefinement
} // namespace xcrack
