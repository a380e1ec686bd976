#include <deal.II/base/exceptions.h>

#include <xcrack/xfem/front_gathering.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace xcrack
{
  template <int dim>
  FrontGathering<dim>::FrontGathering(
    const std::vector<std::vector<FrontPoint<dim>>> &fronts)
    : fronts(fronts)
    , nodes(fronts.size())
  {
    for (const auto &front : fronts)
      {
        Assert(!front.empty(), ExcMessage("A front without points."));
        is_closed.push_back(front.size() > 2 &&
                            front.front().position == front.back().position);
      }
  }



  template <int dim>
  unsigned int
  FrontGathering<dim>::n_fronts() const
  {
    return fronts.size();
  }



  template <int dim>
  bool
  FrontGathering<dim>::closed(const unsigned int f) const
  {
    return is_closed[f];
  }



  template <int dim>
  typename FrontGathering<dim>::Location
  FrontGathering<dim>::locate(const Point<dim> &x) const
  {
    Location best;
    best.distance = std::numeric_limits<double>::max();
    for (unsigned int f = 0; f < fronts.size(); ++f)
      {
        const auto &points = fronts[f];
        if (points.size() == 1)
          {
            const double d = x.distance(points[0].position);
            if (d < best.distance)
              best = {f, 0., d};
            continue;
          }
        for (unsigned int i = 0; i + 1 < points.size(); ++i)
          {
            const Tensor<1, dim> ab =
              points[i + 1].position - points[i].position;
            const double length2 = ab * ab;
            const double t =
              (length2 > 0 ?
                 std::clamp(((x - points[i].position) * ab) / length2, 0., 1.) :
                 0.);
            const double d = x.distance(points[i].position + t * ab);
            if (d < best.distance)
              {
                double s = points[i].s + t * (points[i + 1].s - points[i].s);
                if (is_closed[f] && s >= points.back().s)
                  s -= points.back().s;
                best = {f, s, d};
              }
          }
      }
    return best;
  }



  template <int dim>
  std::vector<double>
  FrontGathering<dim>::targets(const unsigned int f, const double spacing) const
  {
    const double length = fronts[f].back().s;
    if (fronts[f].size() == 1 || length <= 0)
      return {0.};
    const unsigned int n =
      std::max<unsigned int>(is_closed[f] ? 3 : 1,
                             std::lround(length / spacing));
    std::vector<double> s;
    for (unsigned int k = 0; k < n + (is_closed[f] ? 0 : 1); ++k)
      s.push_back(length * k / n);
    return s;
  }



  template <int dim>
  double
  FrontGathering<dim>::separation(const unsigned int f,
                                  const double       s1,
                                  const double       s2) const
  {
    const double d = std::abs(s1 - s2);
    return (is_closed[f] ? std::min(d, fronts[f].back().s - d) : d);
  }



  template <int dim>
  void
  FrontGathering<dim>::set_nodes(const unsigned int         f,
                                 const std::vector<double> &s)
  {
    Assert(!s.empty(), ExcMessage("A front without gathering nodes."));
    Assert(std::is_sorted(s.begin(), s.end()),
           ExcMessage("Gathering nodes must increase along the front."));
    nodes[f] = s;
  }



  template <int dim>
  std::vector<std::pair<unsigned int, double>>
  FrontGathering<dim>::weights(const Location &location) const
  {
    const std::vector<double> &s = nodes[location.front];
    Assert(!s.empty(), ExcMessage("set_nodes() was not called."));
    const unsigned int                           last = s.size() - 1;
    const double                                 x    = location.s;
    std::vector<std::pair<unsigned int, double>> w;
    const auto                                   linear =
      [&w](const unsigned int a, const unsigned int b, const double t) {
        if (t < 1)
          w.emplace_back(a, 1 - t);
        if (t > 0)
          w.emplace_back(b, t);
      };
    if (s.size() == 1)
      w.emplace_back(0, 1.);
    else if (x >= s[0] && x < s[last])
      {
        const unsigned int i =
          std::upper_bound(s.begin(), s.end(), x) - s.begin() - 1;
        linear(i, i + 1, (x - s[i]) / (s[i + 1] - s[i]));
      }
    else if (!is_closed[location.front])
      w.emplace_back(x < s[0] ? 0 : last, 1.);
    else
      {
        // Between the last node and the first, across s = 0.
        const double length = fronts[location.front].back().s;
        const double width  = s[0] + length - s[last];
        double       from   = x - s[last];
        if (from < 0)
          from += length;
        linear(last, 0, std::clamp(from / width, 0., 1.));
      }
    return w;
  }



  template class FrontGathering<2>;
  template class FrontGathering<3>;
} // namespace xcrack
