#include <deal.II/base/numbers.h>
#include <deal.II/base/quadrature_lib.h>

#include <xcrack/fracture/front_basis.h>
#include <xcrack/input_error.h>

#include <algorithm>
#include <cmath>

namespace xcrack
{
  namespace
  {
    /// Legendre polynomial P_n(x) by the three-term recurrence.
    double
    legendre(const unsigned int n, const double x)
    {
      double p0 = 1, p1 = x;
      if (n == 0)
        return p0;
      for (unsigned int k = 2; k <= n; ++k)
        {
          const double p2 = ((2. * k - 1) * x * p1 - (k - 1.) * p0) / k;
          p0              = p1;
          p1              = p2;
        }
      return p1;
    }
  } // namespace



  FrontBasis::Type
  FrontBasis::parse_type(const std::string &name)
  {
    if (name == "legendre")
      return Type::legendre;
    if (name == "lagrange")
      return Type::lagrange;
    check_input(name == "lagrange regularized",
                "Fracture parameters/Smoothing = " + name +
                  ": use legendre, lagrange or lagrange regularized.");
    return Type::lagrange_regularized;
  }



  FrontBasis::FrontBasis()
    : node_s(1, 0.)
    , map(1, 1)
  {
    map(0, 0) = 1;
  }



  FrontBasis::FrontBasis(const Type         type,
                         const unsigned int degree,
                         const double       length,
                         const bool         closed,
                         const unsigned int n_segments)
    : type(type)
    , degree(degree)
    , length(length)
    , closed(closed)
    , segments(std::max(n_segments, closed ? 3u : 1u))
  {
    const double l = length / segments;
    for (unsigned int k = 0; k < segments + (closed ? 0 : 1); ++k)
      node_s.push_back(k * l);

    const unsigned int n = n_test_functions();
    // A_ji = int phi_i psi_j ds, by Gauss rules on sub-intervals of the
    // segments (the hats are smooth on each; at least 64 sub-intervals
    // resolve the highest Fourier mode, degree 7).
    const unsigned int  per_segment = (63 + segments) / segments;
    const QGauss<1>     gauss(8);
    FullMatrix<double>  A(n, n);
    Vector<double>      lumped(n);
    std::vector<double> phi(n), psi(n);
    for (unsigned int k = 0; k < segments * per_segment; ++k)
      for (unsigned int g = 0; g < gauss.size(); ++g)
        {
          const double h = l / per_segment;
          const double s = (k + gauss.point(g)[0]) * h;
          const double w = gauss.weight(g) * h;
          for (unsigned int i = 0; i < n; ++i)
            {
              phi[i] = shape_function(i, s);
              psi[i] = test_function(i, s);
            }
          for (unsigned int j = 0; j < n; ++j)
            {
              lumped[j] += psi[j] * w;
              for (unsigned int i = 0; i < n; ++i)
                A(j, i) += phi[i] * psi[j] * w;
            }
        }

    map.reinit(node_s.size(), n);
    if (type == Type::lagrange_regularized)
      for (unsigned int j = 0; j < n; ++j)
        map(j, j) = 1. / lumped[j];
    else
      {
        A.gauss_jordan();
        FullMatrix<double> E(node_s.size(), n);
        for (unsigned int k = 0; k < node_s.size(); ++k)
          for (unsigned int i = 0; i < n; ++i)
            E(k, i) = shape_function(i, node_s[k]);
        E.mmult(map, A);
      }
  }



  unsigned int
  FrontBasis::n_test_functions() const
  {
    if (length == 0)
      return 1;
    if (type == Type::legendre)
      return closed ? 2 * degree + 1 : degree + 1;
    return node_s.size();
  }



  double
  FrontBasis::hat(const unsigned int j,
                  const double       s,
                  const double       width) const
  {
    double d = std::abs(s - node_s[j]);
    if (closed)
      d = std::min(d, length - d);
    return std::max(0., 1. - d / (width * length / segments));
  }



  double
  FrontBasis::shape_function(const unsigned int i, const double s) const
  {
    if (length == 0)
      return 1;
    if (type == Type::legendre)
      {
        if (!closed)
          return legendre(i, 2 * s / length - 1);
        if (i == 0)
          return 1;
        const double angle = 2 * numbers::PI * ((i + 1) / 2) * s / length;
        return (i % 2 == 1 ? std::cos(angle) : std::sin(angle));
      }
    return hat(i, s, 1);
  }



  double
  FrontBasis::test_function(const unsigned int j, const double s) const
  {
    if (type == Type::lagrange_regularized && length > 0)
      return hat(j, s, 2);
    return shape_function(j, s);
  }



  std::string
  FrontBasis::description() const
  {
    if (length == 0)
      return "tip";
    if (type == Type::legendre)
      return (closed ? "Fourier degree " : "Legendre degree ") +
             std::to_string(degree);
    return (type == Type::lagrange ? "Lagrange, " : "regularised Lagrange, ") +
           std::to_string(segments) + " segments";
  }



  const std::vector<double> &
  FrontBasis::nodes() const
  {
    return node_s;
  }



  std::vector<double>
  FrontBasis::values_at_nodes(const std::vector<double> &b) const
  {
    std::vector<double> values(node_s.size(), 0.);
    for (unsigned int k = 0; k < node_s.size(); ++k)
      for (unsigned int j = 0; j < b.size(); ++j)
        values[k] += map(k, j) * b[j];
    return values;
  }
} // namespace xcrack
