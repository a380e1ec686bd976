#ifndef xcrack_level_set_update_band_grid_h
#define xcrack_level_set_update_band_grid_h

#include <deal.II/base/bounding_box.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>

#include <xcrack/crack/level_set_fields.h>

#include <array>
#include <cstddef>
#include <utility>
#include <vector>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    /**
     * The auxiliary Cartesian grid of the `upwind` update: a lattice over a
     * box around the front, of which only the points in a band (set_active())
     * take part. Finite differences need a lattice, which the adapted
     * hexahedral mesh is not; the band keeps the cost to the front's
     * neighbourhood rather than the body.
     *
     * The lattice is aligned with the body's bounding box: its spacing is
     * adjusted per direction so that the box's faces are lattice planes.
     * On a box-shaped body every mesh node then lies in a grid cell whose
     * corners are all in the body, and the fields come back to the mesh by
     * d-linear interpolation without extrapolating anywhere.
     *
     * The grid is built identically on every rank (it is small next to the
     * mesh): sample() gathers the mesh fields on it from all ranks, and the
     * schemes (hamilton_jacobi.h) then run redundantly, so that the result
     * does not depend on the partition.
     */
    template <int dim>
    class BandGrid
    {
    public:
      /// No point: off the lattice, or not in the band.
      static constexpr std::size_t none = static_cast<std::size_t>(-1);

      /**
       * The lattice of spacing about @p spacing (at most it) over @p box
       * clipped to @p body, aligned with @p body's corners. Throws an
       * InputError naming `Grid spacing` if it would have more than
       * @p max_points points.
       */
      BandGrid(const BoundingBox<dim> &box,
               const BoundingBox<dim> &body,
               const double            spacing,
               const std::size_t       max_points);

      /// The number of lattice points (active or not).
      std::size_t
      size() const;

      /// The position of point @p i.
      Point<dim>
      point(const std::size_t i) const;

      /// The spacing along direction @p d.
      double
      spacing(const unsigned int d) const;

      /// The smallest spacing.
      double
      min_spacing() const;

      /// The active neighbour of point @p i along direction @p d on side
      /// @p side (0: towards lower coordinates, 1: higher), or none.
      std::size_t
      neighbour(const std::size_t  i,
                const unsigned int d,
                const unsigned int side) const;

      /**
       * Which points take part (@p active[i] != 0): the schemes update only
       * these, and a missing neighbour is an inactive or off-lattice one.
       */
      void
      set_active(const std::vector<char> &active);

      bool
      is_active(const std::size_t i) const;

      /// Whether active point @p i has a neighbour missing: the edge of the
      /// band, where the schemes set values without a full stencil.
      bool
      is_edge(const std::size_t i) const;

      /// The number of active points.
      std::size_t
      n_active() const;

      /// No neighbour in a stencil().
      static constexpr unsigned int missing = static_cast<unsigned int>(-1);

      /// The active points' indices, increasing: what the schemes loop
      /// over.
      const std::vector<unsigned int> &
      active_points() const
      {
        return points;
      }

      /// The neighbours of the @p p th active point: entry 2 d + side as
      /// neighbour(), missing for none. A table, because the schemes ask
      /// for them hundreds of times per point.
      const std::array<unsigned int, 2 * dim> &
      stencil(const std::size_t p) const
      {
        return stencils[p];
      }

      /**
       * The Q1 fields lsn and lst of crack @p crack at the lattice points
       * inside the mesh (the smallest value over the cells that contain a
       * point, so that it does not depend on the partition), NaN at the
       * others. Collective.
       */
      std::pair<std::vector<double>, std::vector<double>>
      sample(const LevelSetFields<dim> &fields,
             const unsigned int         crack,
             const MPI_Comm             communicator) const;

      /**
       * The d-linear weights of the active corners of the grid cell that
       * holds @p x, renormalised to sum to 1 (the corners outside the body
       * or the band left out); empty where none is active or @p x is off
       * the lattice.
       */
      std::vector<std::pair<std::size_t, double>>
      weights(const Point<dim> &x) const;

    private:
      /// The index of the point with lattice coordinates @p index.
      std::size_t
      index_of(const std::array<unsigned int, dim> &index) const;

      /// The lattice coordinates of point @p i.
      std::array<unsigned int, dim>
      coordinates(const std::size_t i) const;

      Point<dim>                                     lower;
      std::array<unsigned int, dim>                  n_points;
      std::array<double, dim>                        h;
      std::vector<char>                              active;
      std::vector<unsigned int>                      points;
      std::vector<std::array<unsigned int, 2 * dim>> stencils;
    };
  } // namespace LevelSetUpdate
} // namespace xcrack

#endif
