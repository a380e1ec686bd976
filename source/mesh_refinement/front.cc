#include <xcrack/crack/crack_set.h>
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
      prm.leave_subsection();
    }



    template <int dim>
    void
    Front<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Front");
      band = prm.get_double("Front band");
    }



    template <int dim>
    void
    Front<dim>::mark(
      parallel::distributed::Triangulation<dim> &triangulation) const
    {
      const CrackSet<dim> &cracks = this->get_initial_cracks();
      for (const auto &cell : triangulation.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            double distance = std::numeric_limits<double>::max();
            for (unsigned int c = 0; c < cracks.size(); ++c)
              distance = std::min(distance,
                                  std::hypot(cracks[c].lsn(cell->center()),
                                             cracks[c].lst(cell->center())));
            if (distance < band * cell->diameter())
              cell->set_refine_flag();
          }
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Front,
                           "front",
                           "the cells within Front band of their diameters "
                           "of a crack front are refined (subsection Front).")
  } // namespace MeshRefinement
} // namespace xcrack
