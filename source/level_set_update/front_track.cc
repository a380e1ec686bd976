#include <deal.II/grid/tria.h>

#include <xcrack/level_set_update/front_track.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    template <int dim>
    Tensor<1, dim>
    Sample<dim>::old_direction() const
    {
      return e1 / e1.norm();
    }



    template <int dim>
    Tensor<1, dim>
    Sample<dim>::old_normal() const
    {
      const Tensor<1, dim> t = old_direction();
      Tensor<1, dim>       n = e2 - (e2 * t) * t;
      return n / n.norm();
    }



    template <int dim>
    Tensor<1, dim>
    Sample<dim>::new_direction() const
    {
      return std::cos(angle) * old_direction() + std::sin(angle) * old_normal();
    }



    template <int dim>
    Tensor<1, dim>
    Sample<dim>::new_normal() const
    {
      return -std::sin(angle) * old_direction() +
             std::cos(angle) * old_normal();
    }



    template <int dim>
    Sample<dim>
    Track<dim>::at(double x) const
    {
      if (s.empty())
        return {};
      if (s.size() == 1)
        return samples[0];
      if (closed)
        {
          x = std::fmod(x - s[0], length);
          if (x < 0)
            x += length;
          x += s[0];
          // Between the last point and the first one, across s = L.
          if (x > s.back())
            {
              const double w = (x - s.back()) / (s[0] + length - s.back());
              return samples.back() * (1 - w) + samples[0] * w;
            }
        }
      if (x <= s.front())
        return samples.front();
      if (x >= s.back())
        return samples.back();
      const unsigned int k =
        std::upper_bound(s.begin(), s.end(), x) - s.begin() - 1;
      const double w = (x - s[k]) / (s[k + 1] - s[k]);
      return samples[k] * (1 - w) + samples[k + 1] * w;
    }



    template <int dim>
    bool
    is_closed(const std::vector<FrontPoint<dim>> &front)
    {
      return front.size() > 2 &&
             front.front().position == front.back().position;
    }



    template <int dim>
    std::vector<Track<dim>>
    make_tracks(const unsigned int                               crack,
                const std::vector<FrontMove<dim>>               &moves,
                const std::vector<std::vector<FrontPoint<dim>>> &fronts,
                double &largest_advance)
    {
      std::vector<Track<dim>> unsorted(fronts.size());
      largest_advance = 0;
      for (const FrontMove<dim> &m : moves)
        if (m.crack == crack)
          {
            AssertIndexRange(m.front, fronts.size());
            unsorted[m.front].s.push_back(m.point.s);
            unsorted[m.front].samples.push_back(
              {m.angle, m.advance, m.point.e1, m.point.e2});
            largest_advance = std::max(largest_advance, m.advance);
          }
      std::vector<Track<dim>> tracks(fronts.size());
      for (unsigned int f = 0; f < fronts.size(); ++f)
        {
          const Track<dim>         &t = unsorted[f];
          std::vector<unsigned int> order(t.s.size());
          std::iota(order.begin(), order.end(), 0u);
          std::sort(order.begin(), order.end(), [&](auto a, auto b) {
            return t.s[a] < t.s[b];
          });
          for (const unsigned int k : order)
            {
              tracks[f].s.push_back(t.s[k]);
              tracks[f].samples.push_back(t.samples[k]);
            }
          tracks[f].closed = is_closed(fronts[f]);
          tracks[f].length = (fronts[f].empty() ? 0. : fronts[f].back().s);
        }
      return tracks;
    }



    template <int dim>
    std::tuple<unsigned int, double, Point<dim>>
    project(const std::vector<std::vector<FrontPoint<dim>>> &fronts,
            const Point<dim>                                &x)
    {
      double       distance = std::numeric_limits<double>::max();
      unsigned int front    = 0;
      double       s        = 0;
      Point<dim>   nearest;
      for (unsigned int f = 0; f < fronts.size(); ++f)
        {
          const auto &points = fronts[f];
          // A 2D tip is a front of one point; else its segments.
          for (unsigned int k = 0; k + (points.size() > 1 ? 1 : 0) <
                                   std::max<std::size_t>(points.size(), 1);
               ++k)
            {
              const FrontPoint<dim> &a = points[k];
              const FrontPoint<dim> &b =
                (points.size() > 1 ? points[k + 1] : points[k]);
              const Tensor<1, dim> edge = b.position - a.position;
              const double         w =
                (edge.norm_square() > 0 ?
                   std::clamp((x - a.position) * edge / edge.norm_square(),
                              0.,
                              1.) :
                   0.);
              const Point<dim> y = a.position + w * edge;
              if (x.distance(y) < distance)
                {
                  distance = x.distance(y);
                  front    = f;
                  s        = (1 - w) * a.s + w * b.s;
                  nearest  = y;
                }
            }
        }
      return {front, s, nearest};
    }



    template <int dim>
    FrontCellSizes
    front_cell_sizes(const LevelSetFields<dim> &fields,
                     const unsigned int         crack,
                     const MPI_Comm             communicator)
    {
      const std::vector<double> lsn = fields.vertex_values(crack, true);
      const std::vector<double> lst = fields.vertex_values(crack, false);
      // The finest and minus the largest, for one reduction.
      std::vector<double> sizes(2, std::numeric_limits<double>::max());
      for (const auto &cell :
           fields.get_dof_handler().get_triangulation().active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            if (std::hypot(lsn[cell->vertex_index(v)],
                           lst[cell->vertex_index(v)]) < cell->diameter())
              {
                sizes[0] = std::min(sizes[0], cell->diameter());
                sizes[1] = std::min(sizes[1], -cell->diameter());
              }
      Utilities::MPI::min(sizes, communicator, sizes);
      return {sizes[0],
              (sizes[1] == std::numeric_limits<double>::max() ? 0. :
                                                                -sizes[1])};
    }



    template <int dim>
    BoundingBox<dim>
    front_box(const std::vector<std::vector<FrontPoint<dim>>> &fronts,
              const double                                     margin)
    {
      Point<dim> lower, upper;
      for (unsigned int d = 0; d < dim; ++d)
        {
          lower[d] = std::numeric_limits<double>::max();
          upper[d] = -std::numeric_limits<double>::max();
        }
      for (const auto &front : fronts)
        for (const FrontPoint<dim> &point : front)
          for (unsigned int d = 0; d < dim; ++d)
            {
              lower[d] = std::min(lower[d], point.position[d] - margin);
              upper[d] = std::max(upper[d], point.position[d] + margin);
            }
      return BoundingBox<dim>({lower, upper});
    }



    double
    default_band(const double enrichment_radius,
                 const double h,
                 const double largest_advance)
    {
      return 2 * std::max(enrichment_radius, 6 * h) + 2 * largest_advance;
    }



#define XCRACK_INSTANTIATE(dim)                                             \
  template struct Sample<dim>;                                              \
  template struct Track<dim>;                                               \
  template std::vector<Track<dim>> make_tracks(                             \
    const unsigned int,                                                     \
    const std::vector<FrontMove<dim>> &,                                    \
    const std::vector<std::vector<FrontPoint<dim>>> &,                      \
    double &);                                                              \
  template bool is_closed(const std::vector<FrontPoint<dim>> &);            \
  template std::tuple<unsigned int, double, Point<dim>> project(            \
    const std::vector<std::vector<FrontPoint<dim>>> &, const Point<dim> &); \
  template FrontCellSizes   front_cell_sizes(const LevelSetFields<dim> &,   \
                                             const unsigned int,            \
                                             const MPI_Comm);               \
  template BoundingBox<dim> front_box(                                      \
    const std::vector<std::vector<FrontPoint<dim>>> &, const double);
    XCRACK_INSTANTIATE(2)
    XCRACK_INSTANTIATE(3)
#undef XCRACK_INSTANTIATE
  } // namespace LevelSetUpdate
} // namespace xcrack
