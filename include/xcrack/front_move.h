#ifndef xcrack_front_move_h
#define xcrack_front_move_h

#include <deal.II/base/point.h>

#include <xcrack/crack/crack_geometry.h>

#include <array>
#include <boost/serialization/array.hpp>
#include <cmath>

namespace xcrack
{
  using namespace dealii;

  /**
   * How one point of a front moves in a propagation step: where K was
   * extracted (the point with its frame and abscissa), what the growth
   * model made of it, and the advance. Propagation fills it; the level-set
   * update and the termination criteria read it.
   */
  template <int dim>
  struct FrontMove
  {
    /// The crack and the front (numbered crack after crack) of the point.
    unsigned int    crack = 0, front = 0;
    FrontPoint<dim> point;
    /// The equivalent K at the maximum of the load cycle, and its range.
    double k_eq = 0, delta_k = 0;
    /// K_I, K_II, K_III at the minimum of the load cycle.
    std::array<double, 3> k_minimum = {{0, 0, 0}};
    /// da/dN (or a relative speed for a quasi-static law, 1 at the most
    /// loaded point).
    double rate = 0;
    /// Lips that passed through each other at the point (K_I < 0 without
    /// contact): it does not grow.
    bool closed = false;
    /// Kink angle from e1 towards e2 (radians).
    double angle = 0;
    /// The advance in this step, and the part of it that catches up with
    /// the previous step (Propagation::catch_up()).
    double advance = 0, catch_up = 0;

    /// The new direction of propagation e1' (e1 turned by the kink angle).
    Tensor<1, dim>
    direction() const
    {
      return std::cos(angle) * point.e1 + std::sin(angle) * point.e2;
    }

    /// The new normal e2' (e2 turned by the kink angle).
    Tensor<1, dim>
    normal() const
    {
      return -std::sin(angle) * point.e1 + std::cos(angle) * point.e2;
    }

    /// Where the point goes.
    Point<dim>
    new_position() const
    {
      return point.position + advance * direction();
    }

    /// Write or read with a boost archive (checkpoints).
    template <class Archive>
    void
    serialize(Archive &archive, const unsigned int)
    {
      archive &crack &front &point &k_eq &delta_k &k_minimum &rate &closed
        &angle &advance &catch_up;
    }
  };
} // namespace xcrack

#endif
