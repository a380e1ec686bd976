#include <xcrack/crack/facet_crack.h>
#include <xcrack/input_error.h>

#include <algorithm>
#include <fstream>
#include <limits>

namespace xcrack
{
  template <int dim>
  FacetCrack<dim>::FacetCrack(const std::string &file_name,
                              const std::string &entry)
  {
    std::ifstream in(file_name);
    check_input(static_cast<bool>(in),
                entry + " = " + file_name +
                  ": cannot open this file for reading (a relative name is "
                  "read from the directory of the parameter file that sets "
                  "it).");
    facets = FacetSurface<dim>::read_vtu(in, entry + " = " + file_name);
  }



  template <int dim>
  double
  FacetCrack<dim>::lsn(const Point<dim> &p) const
  {
    return facets.lsn(p);
  }



  template <int dim>
  double
  FacetCrack<dim>::lst(const Point<dim> &p) const
  {
    return facets.lst(p);
  }



  template <int dim>
  std::vector<FrontPoint<dim>>
  FacetCrack<dim>::front(const unsigned int, const BoundingBox<dim> &) const
  {
    std::vector<FrontPoint<dim>> points;
    for (const auto &nodes : facets.fronts())
      {
        std::vector<FrontPoint<dim>> front;
        for (const auto &node : nodes)
          {
            FrontPoint<dim> p;
            p.position = node.position;
            p.e1       = node.e1;
            if constexpr (dim == 2)
              {
                p.e2[0] = 0. - p.e1[1];
                p.e2[1] = p.e1[0];
              }
            else
              {
                const Tensor<1, dim> n = facets.nearest(p.position).second;
                p.e2                   = n - (n * p.e1) * p.e1;
                p.e2 /= p.e2.norm();
                p.e3 = cross_product_3d(p.e1, p.e2);
              }
            front.push_back(p);
          }
        orient_front(front);
        points.insert(points.end(), front.begin(), front.end());
      }
    return points;
  }



  template <int dim>
  BoundingBox<dim>
  FacetCrack<dim>::bounding_box(const BoundingBox<dim> &body) const
  {
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = std::numeric_limits<double>::max();
        upper[d] = -std::numeric_limits<double>::max();
      }
    for (const auto &facet : facets.facets())
      for (const Point<dim> &x : facet.corners)
        for (unsigned int d = 0; d < dim; ++d)
          {
            lower[d] = std::min(lower[d], x[d]);
            upper[d] = std::max(upper[d], x[d]);
          }
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = std::max(lower[d], body.lower_bound(d));
        upper[d] = std::min(upper[d], body.upper_bound(d));
      }
    return BoundingBox<dim>(std::make_pair(lower, upper));
  }



  template <int dim>
  const FacetSurface<dim> &
  FacetCrack<dim>::surface() const
  {
    return facets;
  }



  template class FacetCrack<2>;
  template class FacetCrack<3>;
} // namespace xcrack
