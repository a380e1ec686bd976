#include <deal.II/base/mpi.h>

#include <xcrack/crack/crack_surface.h>
#include <xcrack/front_move.h>
#include <xcrack/level_set_update/front_track.h>
#include <xcrack/termination_criteria/crack_leaves_body.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

namespace xcrack
{
  namespace TerminationCriteria
  {
    namespace
    {
      /**
       * The distance along the unit direction @p d from @p x to the face
       * of the boundary with vertices @p v (a segment in 2D; in 3D a
       * quadrilateral, split into two triangles), or infinity if the ray
       * misses it.
       */
      template <int dim>
      double
      ray_to_face(const Point<dim>              &x,
                  const Tensor<1, dim>          &d,
                  const std::vector<Point<dim>> &v)
      {
        double hit = std::numeric_limits<double>::infinity();
        if constexpr (dim == 2)
          {
            // x + t d = v0 + s (v1 - v0), 0 <= s <= 1.
            const Tensor<1, 2> e = v[1] - v[0], w = v[0] - x;
            const double       det = d[1] * e[0] - d[0] * e[1];
            if (std::abs(det) > 1e-14 * e.norm())
              {
                const double t  = (w[1] * e[0] - w[0] * e[1]) / det;
                const double sv = (w[1] * d[0] - w[0] * d[1]) / det;
                if (sv >= 0 && sv <= 1)
                  hit = t;
              }
          }
        else
          // Moeller and Trumbore on the triangles (0, 1, 2) and (1, 3, 2)
          // of deal.II's vertex order.
          for (const std::array<unsigned int, 3> &t :
               {std::array<unsigned int, 3>{{0, 1, 2}},
                std::array<unsigned int, 3>{{1, 3, 2}}})
            {
              const Tensor<1, dim> e1  = v[t[1]] - v[t[0]],
                                   e2  = v[t[2]] - v[t[0]];
              const Tensor<1, dim> p   = cross_product_3d(d, e2);
              const double         det = e1 * p;
              if (std::abs(det) <= 1e-14 * e1.norm() * e2.norm())
                continue;
              const Tensor<1, dim> q = x - v[t[0]];
              const double         a = (q * p) / det;
              const Tensor<1, dim> r = cross_product_3d(q, e1);
              const double         b = (d * r) / det;
              if (a >= 0 && b >= 0 && a + b <= 1)
                hit = std::min(hit, (e2 * r) / det);
            }
        return hit;
      }
    } // namespace



    template <int dim>
    void
    CrackLeavesBody<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Crack leaves body");
      prm.declare_entry(
        "Through crack",
        "continue",
        Patterns::Selection("continue|stop"),
        "3D: what a crack whose front splits into open fronts (a surface "
        "crack that broke through the back wall, now a through crack with "
        "a front on each side; at most two fronts from each it started "
        "with) does: grow on, with K at every front, or end the run (a "
        "leak-before-break assessment ends at the leak).");
      prm.leave_subsection();
    }



    template <int dim>
    void
    CrackLeavesBody<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Crack leaves body");
      stop_at_through_crack = (prm.get("Through crack") == "stop");
    }



    template <int dim>
    Verdict
    CrackLeavesBody<dim>::check()
    {
      Verdict     verdict;
      const auto &surfaces = this->get_crack_surfaces();
      if (n_fronts.empty())
        for (const auto &surface : surfaces)
          n_fronts.push_back(surface.fronts().size());
      if (initial_fronts.empty())
        initial_fronts = n_fronts;
      for (unsigned int c = 0; c < surfaces.size(); ++c)
        if (dim == 3 && !stop_at_through_crack &&
            surfaces[c].fronts().size() > n_fronts[c] &&
            surfaces[c].fronts().size() <= 2 * initial_fronts[c] &&
            std::none_of(surfaces[c].fronts().begin(),
                         surfaces[c].fronts().end(),
                         [](const auto &front) {
                           return LevelSetUpdate::is_closed(front);
                         }))
          {
            // More fronts, every one open (ending on the body's surface),
            // at most two from each front the crack started with: the
            // crack broke through a wall and grows on as a through crack.
            // (A piece of crack inside the body would be closed; fronts
            // that keep splitting are the fields losing the crack.)
            this->get_pcout()
              << "Crack " << c + 1 << " broke through the body's surface: "
              << surfaces[c].fronts().size() << " fronts instead of "
              << n_fronts[c]
              << ", it grows on as a through crack (Termination "
                 "criteria/Crack leaves body/Through crack)."
              << std::endl;
            n_fronts[c] = surfaces[c].fronts().size();
          }
        else if (surfaces[c].fronts().size() != n_fronts[c])
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
            else if (dim == 3 && surfaces[c].fronts().size() > n_fronts[c])
              reason << ": it broke through the body's surface (Termination "
                        "criteria/Crack leaves body/Through crack = stop, or "
                        "a piece of crack inside the body)";
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
          const MPI_Comm   comm = this->get_mpi_communicator();
          const Point<dim> x    = m.new_position();
          double           h    = -1;
          for (const auto &cell :
               this->get_triangulation().active_cell_iterators())
            if (cell->is_locally_owned() && cell->point_inside(x))
              {
                h = cell->diameter();
                break;
              }
          h = Utilities::MPI::max(h, comm);
          if (h < 0)
            {
              std::ostringstream reason;
              reason << "the tip of crack " << m.crack + 1 << " at ("
                     << m.point.position << ") would leave the body";
              verdict.stop   = true;
              verdict.reason = reason.str();
              return verdict;
            }
          // A ligament ahead of the new tip shorter than its cell is cut
          // through by the discrete crack: the part it holds comes loose and
          // the next system is singular. The crack has reached the surface.
          const Tensor<1, dim> d        = m.direction() / m.direction().norm();
          double               ligament = std::numeric_limits<double>::max();
          for (const auto &cell :
               this->get_triangulation().active_cell_iterators())
            if (cell->is_locally_owned() && cell->at_boundary())
              for (const auto f : cell->face_indices())
                if (cell->face(f)->at_boundary())
                  {
                    std::vector<Point<dim>> vertices;
                    for (const auto v : cell->face(f)->vertex_indices())
                      vertices.push_back(cell->face(f)->vertex(v));
                    const double t = ray_to_face(x, d, vertices);
                    if (t >= 0)
                      ligament = std::min(ligament, t);
                  }
          ligament = Utilities::MPI::min(ligament, comm);
          if (ligament < h)
            {
              std::ostringstream reason;
              reason << "the tip of crack " << m.crack + 1 << " at ("
                     << m.point.position
                     << ") would come within a cell of the body's surface "
                        "(ligament "
                     << ligament << " < cell " << h
                     << "): the crack cuts through";
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
      // The steps left: for each moving point, the distance along its
      // direction to the first boundary face ahead (holes included) over
      // its advance; points on the boundary already (the ends of a surface
      // crack's front) are left out.
      double left = std::numeric_limits<double>::infinity();
      for (const auto &cell : this->get_triangulation().active_cell_iterators())
        if (cell->is_locally_owned() && cell->at_boundary())
          for (const auto f : cell->face_indices())
            if (cell->face(f)->at_boundary())
              {
                std::vector<Point<dim>> vertices;
                for (const auto v : cell->face(f)->vertex_indices())
                  vertices.push_back(cell->face(f)->vertex(v));
                for (const FrontMove<dim> &m : this->get_front_moves())
                  if (m.advance > 0)
                    {
                      const Tensor<1, dim> d =
                        m.direction() / m.direction().norm();
                      const double t =
                        ray_to_face(m.point.position, d, vertices);
                      if (t > 1e-6 * m.advance)
                        left = std::min(left, t / m.advance);
                    }
              }
      left = Utilities::MPI::min(left, this->get_mpi_communicator());
      if (!std::isfinite(left))
        return 0;
      const double done = this->get_step() + 1;
      return done / (done + std::max(left - 1, 0.));
    }



    template <int dim>
    void
    CrackLeavesBody<dim>::save(Plugins::State &state) const
    {
      state["fronts"]         = Plugins::pack(n_fronts);
      state["initial fronts"] = Plugins::pack(initial_fronts);
    }



    template <int dim>
    void
    CrackLeavesBody<dim>::load(const Plugins::State &state)
    {
      n_fronts       = Plugins::unpack(state, "fronts", n_fronts);
      initial_fronts = Plugins::unpack(state, "initial fronts", n_fronts);
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           CrackLeavesBody,
                           "crack leaves body",
                           "a 2D tip would leave the body or come within a "
                           "cell of its surface, or a crack's fronts change "
                           "in number (but a 3D crack breaking through a "
                           "wall: subsection Crack leaves body).")
  } // namespace TerminationCriteria
} // namespace xcrack
