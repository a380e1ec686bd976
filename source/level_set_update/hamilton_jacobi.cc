#include <xcrack/level_set_update/hamilton_jacobi.h>

#include <algorithm>
#include <cmath>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    namespace HamiltonJacobi
    {
      namespace
      {
        /// The one-sided differences of @p phi at the @p p th active point
        /// along @p d: (backward, forward), 0 towards a missing neighbour.
        /// Godunov's rule then reads a missing side as bringing no
        /// information: an edge point moves with what comes from inside the
        /// band, and a difference is never taken downwind (unstable).
        template <int dim>
        std::pair<double, double>
        differences(const BandGrid<dim>       &grid,
                    const std::vector<double> &phi,
                    const std::size_t          p,
                    const unsigned int         d)
        {
          const auto        &stencil = grid.stencil(p);
          const unsigned int lo = stencil[2 * d], hi = stencil[2 * d + 1];
          const unsigned int i = grid.active_points()[p];
          const double       h = grid.spacing(d);
          return {(lo == BandGrid<dim>::missing ? 0. : (phi[i] - phi[lo]) / h),
                  (hi == BandGrid<dim>::missing ? 0. : (phi[hi] - phi[i]) / h)};
        }



        /**
         * |grad phi| at the @p p th active point by Godunov's upwind rule for a
         * front moving along grad phi (@p positive) or against it: of the two
         * one-sided differences per direction, the one the information
         * comes from.
         */
        template <int dim>
        double
        godunov_norm(const BandGrid<dim>       &grid,
                     const std::vector<double> &phi,
                     const std::size_t          p,
                     const bool                 positive)
        {
          double sum = 0;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const auto [a, b] = differences(grid, phi, p, d);
              sum += (positive ? std::max(std::pow(std::max(a, 0.), 2),
                                          std::pow(std::min(b, 0.), 2)) :
                                 std::max(std::pow(std::min(a, 0.), 2),
                                          std::pow(std::max(b, 0.), 2)));
            }
          return std::sqrt(sum);
        }



      } // namespace



      unsigned int
      steady_iterations(const double width, const double dt, const double h)
      {
        return static_cast<unsigned int>(
                 std::ceil(1.5 * width / dt + 2 * h / dt)) +
               10;
      }



      template <int dim>
      Tensor<1, dim>
      gradient(const BandGrid<dim>       &grid,
               const std::vector<double> &phi,
               const std::size_t          i)
      {
        Tensor<1, dim> g;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const std::size_t lo = grid.neighbour(i, d, 0),
                              hi = grid.neighbour(i, d, 1);
            const double h       = grid.spacing(d);
            if (lo != BandGrid<dim>::none && hi != BandGrid<dim>::none)
              g[d] = (phi[hi] - phi[lo]) / (2 * h);
            else if (hi != BandGrid<dim>::none)
              g[d] = (phi[hi] - phi[i]) / h;
            else if (lo != BandGrid<dim>::none)
              g[d] = (phi[i] - phi[lo]) / h;
          }
        return g;
      }



      template <int dim>
      void
      propagate(const BandGrid<dim>       &grid,
                const std::vector<double> &speed,
                std::vector<double>       &phi)
      {
        const std::vector<unsigned int> &points  = grid.active_points();
        double                           fastest = 0;
        for (const unsigned int i : points)
          fastest = std::max(fastest, std::abs(speed[i]));
        if (fastest == 0)
          return;
        const double       dx = grid.min_spacing();
        const unsigned int n_steps =
          std::max(1., std::ceil(fastest / (0.5 * dx)));
        const double dt = 1. / n_steps;

        std::vector<double> next(points.size());
        for (unsigned int step = 0; step < n_steps; ++step)
          {
            for (std::size_t p = 0; p < points.size(); ++p)
              {
                const unsigned int i = points[p];
                next[p] =
                  (speed[i] == 0 ?
                     phi[i] :
                     phi[i] - dt * speed[i] *
                                godunov_norm(grid, phi, p, speed[i] > 0));
              }
            for (std::size_t p = 0; p < points.size(); ++p)
              phi[points[p]] = next[p];
          }
      }



      template <int dim>
      unsigned int
      reinitialise(const BandGrid<dim> &grid,
                   std::vector<double> &phi,
                   const double         width,
                   const double         tolerance)
      {
        const std::vector<unsigned int> &points = grid.active_points();
        const double                     dx     = grid.min_spacing();
        const std::vector<double>        phi0   = phi;
        // The points next to the zero set: set once by projection on it.
        std::vector<std::size_t> free;
        for (std::size_t p = 0; p < points.size(); ++p)
          {
            const unsigned int i            = points[p];
            const auto        &stencil      = grid.stencil(p);
            bool               next_to_zero = (phi0[i] == 0);
            double             norm2        = 0;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const unsigned int lo = stencil[2 * d], hi = stencil[2 * d + 1];
                double             g = 0;
                for (const unsigned int j : {lo, hi})
                  if (j != BandGrid<dim>::missing)
                    {
                      next_to_zero =
                        next_to_zero || (phi0[j] > 0) != (phi0[i] > 0);
                      g = std::max(g, std::abs(phi0[j] - phi0[i]));
                    }
                if (lo != BandGrid<dim>::missing &&
                    hi != BandGrid<dim>::missing)
                  g = std::max(g, std::abs(phi0[hi] - phi0[lo]) / 2);
                norm2 += std::pow(g / grid.spacing(d), 2);
              }
            if (next_to_zero)
              phi[i] = (norm2 > 0 ? phi0[i] / std::sqrt(norm2) : 0.);
            else
              free.push_back(p);
          }

        const double       dt = 0.5 * dx;
        const unsigned int iterations =
          steady_iterations(width, dt, grid.min_spacing());
        std::vector<double> next(free.size());
        unsigned int        k = 0;
        for (; k < iterations; ++k)
          {
            double change = 0;
            for (std::size_t f = 0; f < free.size(); ++f)
              {
                const std::size_t  p = free[f];
                const unsigned int i = points[p];
                const double       s =
                  phi0[i] / std::sqrt(phi0[i] * phi0[i] + dx * dx);
                next[f] =
                  phi[i] - dt * s * (godunov_norm(grid, phi, p, s > 0) - 1);
                change = std::max(change, std::abs(next[f] - phi[i]));
              }
            for (std::size_t f = 0; f < free.size(); ++f)
              phi[points[free[f]]] = next[f];
            if (change < tolerance * dx)
              break;
          }
        return k + 1;
      }



      template <int dim>
      unsigned int
      orthogonalise(const BandGrid<dim>       &grid,
                    const std::vector<double> &phi,
                    std::vector<double>       &psi,
                    const double               width,
                    const double               tolerance)
      {
        const std::vector<unsigned int> &points = grid.active_points();
        const double                     dx     = grid.min_spacing();
        // The velocity S(phi) n, fixed during the iterations.
        std::vector<std::size_t>    moving;
        std::vector<Tensor<1, dim>> velocity;
        for (std::size_t p = 0; p < points.size(); ++p)
          {
            const unsigned int   i = points[p];
            const Tensor<1, dim> g = gradient(grid, phi, i);
            if (g.norm() == 0)
              continue;
            moving.push_back(p);
            velocity.push_back(phi[i] / std::sqrt(phi[i] * phi[i] + dx * dx) *
                               g / g.norm());
          }

        const double       dt = 0.5 * dx;
        const unsigned int iterations =
          steady_iterations(width, dt, grid.min_spacing());
        std::vector<double> next(moving.size());
        unsigned int        k = 0;
        for (; k < iterations; ++k)
          {
            double change = 0;
            for (std::size_t m = 0; m < moving.size(); ++m)
              {
                const std::size_t  p    = moving[m];
                const unsigned int i    = points[p];
                double             rate = 0;
                for (unsigned int d = 0; d < dim; ++d)
                  {
                    const auto [a, b] = differences(grid, psi, p, d);
                    rate += velocity[m][d] * (velocity[m][d] > 0 ? a : b);
                  }
                next[m] = psi[i] - dt * rate;
                change  = std::max(change, std::abs(next[m] - psi[i]));
              }
            for (std::size_t m = 0; m < moving.size(); ++m)
              psi[points[moving[m]]] = next[m];
            if (change < tolerance * dx)
              break;
          }
        return k + 1;
      }



      template <class Band>
      Iterations
      move_front(const Band                &grid,
                 const std::vector<double> &kink,
                 const std::vector<double> &advance,
                 const double               width,
                 std::vector<double>       &phi,
                 std::vector<double>       &psi)
      {
        // 1. The extension plane turns: a point at distance r from the
        // front on a zero set at angle theta moves with normal speed psi g
        // = r cos(theta) g, which turns the zero set at the rate g
        // cos(theta); over a unit of time by gd(g) (the Gudermannian), the
        // kink for g = asinh(tan(kink)). (The criteria's kinks stay below
        // 71 degrees; the bound keeps the speed finite on any input.)
        std::vector<double> speed(grid.size(), 0.);
        for (std::size_t i = 0; i < grid.size(); ++i)
          if (grid.is_active(i))
            speed[i] = std::max(psi[i], 0.) *
                       std::asinh(std::tan(std::clamp(kink[i], -1.5, 1.5)));
        propagate(grid, speed, phi);
        // 2. The plane through the front moves with it.
        for (std::size_t i = 0; i < grid.size(); ++i)
          if (grid.is_active(i))
            speed[i] = advance[i] * std::cos(kink[i]);
        propagate(grid, speed, psi);
        // 3.-5.
        Iterations n;
        n.reinitialise_phi = reinitialise(grid, phi, width);
        n.orthogonalise    = orthogonalise(grid, phi, psi, width);
        n.reinitialise_psi = reinitialise(grid, psi, width);
        return n;
      }



#define XCRACK_INSTANTIATE(dim)                                      \
  template void           propagate(const BandGrid<dim> &,           \
                                    const std::vector<double> &,     \
                                    std::vector<double> &);          \
  template unsigned int   reinitialise(const BandGrid<dim> &,        \
                                       std::vector<double> &,        \
                                       const double,                 \
                                       const double);                \
  template unsigned int   orthogonalise(const BandGrid<dim> &,       \
                                        const std::vector<double> &, \
                                        std::vector<double> &,       \
                                        const double,                \
                                        const double);               \
  template Iterations     move_front(const BandGrid<dim> &,          \
                                     const std::vector<double> &,    \
                                     const std::vector<double> &,    \
                                     const double,                   \
                                     std::vector<double> &,          \
                                     std::vector<double> &);         \
  template Iterations     move_front(const SimplexBand<dim> &,       \
                                     const std::vector<double> &,    \
                                     const std::vector<double> &,    \
                                     const double,                   \
                                     std::vector<double> &,          \
                                     std::vector<double> &);         \
  template Tensor<1, dim> gradient(const BandGrid<dim> &,            \
                                   const std::vector<double> &,      \
                                   const std::size_t);
      XCRACK_INSTANTIATE(2)
      XCRACK_INSTANTIATE(3)
#undef XCRACK_INSTANTIATE
    } // namespace HamiltonJacobi
  }   // namespace LevelSetUpdate
} // namespace xcrack
