#include <deal.II/base/mpi.h>

#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>

#include <xcrack/crack/crack_surface.h>
#include <xcrack/front_move.h>
#include <xcrack/termination_criteria/crack_leaves_body.h>

#include <sstream>

namespace xcrack
{
  namespace TerminationCriteria
  {
    template <int dim>
    Verdict
    CrackLeavesBody<dim>::check()
    {
      Verdict     verdict;
      const auto &surfaces = this->get_crack_surfaces();
      if (n_fronts.empty())
        for (const auto &surface : surfaces)
          n_fronts.push_back(surface.fronts().size());
      for (unsigned int c = 0; c < surfaces.size(); ++c)
        if (surfaces[c].fronts().size() != n_fronts[c])
          {
            std::ostringstream reason;
            reason << "crack " << c + 1 << " now has "
                   << surfaces[c].fronts().size()
                   << (dim == 2 ? " tips" : " fronts") << " instead of "
                   << n_fronts[c];
            // A 2D crack gains tips only through a new piece: one the
            // level sets made inside the body, where there is none.
            if (dim == 2 && surfaces[c].fronts().size() > n_fronts[c])
              {
                reason << ": a piece of crack appeared inside the body (tips";
                for (const auto &front : surfaces[c].fronts())
                  reason << " (" << front[0].position << ")";
                reason << "); the level-set update lost the crack's shape "
                          "(a crack that turned strongly)";
              }
            else
              reason << ": it reached the surface of the body";
            verdict.stop   = true;
            verdict.reason = reason.str();
            return verdict;
          }
      if (dim == 3)
        return verdict;
      // A 2D tip that the next advance would put outside the body.
      for (const FrontMove<dim> &m : this->get_front_moves())
        {
          if (m.advance == 0)
            continue;
          const Point<dim> x      = m.new_position();
          bool             inside = false;
          for (const auto &cell :
               this->get_triangulation().active_cell_iterators())
            if (cell->is_locally_owned() && cell->point_inside(x))
              {
                inside = true;
                break;
              }
          if (!Utilities::MPI::logical_or(inside, this->get_mpi_communicator()))
            {
              std::ostringstream reason;
              reason << "the tip of crack " << m.crack + 1 << " at ("
                     << m.point.position << ") would leave the body";
              verdict.stop   = true;
              verdict.reason = reason.str();
              return verdict;
            }
        }
      return verdict;
    }

    template <int dim>
    double
    CrackLeavesBody<dim>::progress() const
    {
      // Every rank holds the whole coarse mesh (its artificial cells): a
      // point is inside the body if some active cell holds it, here.
      const GridTools::Cache<dim> cache(this->get_triangulation());
      typename Triangulation<dim>::active_cell_iterator hint;
      const auto inside = [&](const Point<dim> &x) {
        try
          {
            const auto found =
              GridTools::find_active_cell_around_point(cache, x, hint);
            // (The search may return the nearest cell of a point outside.)
            if (found.first.state() != IteratorState::valid ||
                !GeometryInfo<dim>::is_inside_unit_cell(found.second, 1e-10))
              return false;
            hint = found.first;
            return true;
          }
        catch (...)
          {
            return false;
          }
      };
      // At most a thousand steps ahead: beyond, the estimate is of no use.
      constexpr unsigned int most = 1000;
      unsigned int           left = most;
      for (const FrontMove<dim> &m : this->get_front_moves())
        {
          if (!(m.advance > 0))
            continue;
          const Tensor<1, dim> d = m.direction() / m.direction().norm();
          if (!inside(m.point.position + m.advance * d))
            continue;
          unsigned int k = 2;
          while (k < left && inside(m.point.position + k * m.advance * d))
            ++k;
          left = std::min(left, k);
        }
      if (left == most)
        return 0;
      const double done = this->get_step() + 1;
      return done / (done + left - 1);
    }



    template <int dim>
    void
    CrackLeavesBody<dim>::save(Plugins::State &state) const
    {
      state["fronts"] = Plugins::pack(n_fronts);
    }



    template <int dim>
    void
    CrackLeavesBody<dim>::load(const Plugins::State &state)
    {
      n_fronts = Plugins::unpack(state, "fronts", n_fronts);
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           CrackLeavesBody,
                           "crack leaves body",
                           "a 2D tip would leave the body, or a crack's "
                           "fronts change in number.")
  } // namespace TerminationCriteria
} // namespace xcrack
