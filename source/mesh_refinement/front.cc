#include <xcrack/crack/level_set_fields.h>
#include <xcrack/input_error.h>
#include <xcrack/mesh_refinement/front.h>

#include <cmath>
#include <limits>

namespace xcrack
{
  namespace MeshRefinement
  {
    template <int dim>
    void
    Front<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Front");
      prm.declare_entry("Front band",
                        "2",
                        Patterns::Double(0),
                        "Refine the cells whose centre lies within this many "
                        "of their own diameters of a crack front (r = "
                        "sqrt(lsn^2 + lst^2)).");
      prm.declare_entry(
        "Coarsening band",
        "0",
        Patterns::Double(0),
        "Coarsen the cells whose centre lies farther than "
        "this many of their own diameters from every front "
        "(0: never; else more than twice the Front band, or the "
        "cells would be refined and coarsened in turn), so that the "
        "fine cells follow growing cracks.");
      prm.leave_subsection();
    }



    template <int dim>
    void
    Front<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Front");
      band            = prm.get_double("Front band");
      coarsening_band = prm.get_double("Coarsening band");
      check_input(coarsening_band == 0 || coarsening_band > 2 * band,
                  "Mesh refinement/Front/Coarsening band = " +
                    prm.get("Coarsening band") +
                    ": must exceed twice the Front band (" +
                    prm.get("Front band") + "), or be 0.");
    }



    template <int dim>
    void
    Front<dim>::mark(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      // r = sqrt(lsn^2 + lst^2) at the centre.
      const std::vector<double> distances =
        this->get_level_set_fields().cell_front_distances();
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            const double distance = distances[cell->active_cell_index()];
            if (distance < band * cell->diameter())
              cell->set_refine_flag();
            else if (coarsening_band > 0 &&
                     distance > coarsening_band * cell->diameter())
              cell->set_coarsen_flag();
          }
    }

    template <int dim>
    bool
    Front<dim>::follows_fronts() const
    {
      return true;
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Front,
                           "front",
                           "the cells within Front band of their diameters "
                           "of a crack front are refined (subsection Front).")
  } // namespace MeshRefinement
} // namespace xcrack
