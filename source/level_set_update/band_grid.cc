#include <deal.II/fe/mapping_q1.h>

#include <xcrack/input_error.h>
#include <xcrack/level_set_update/band_grid.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace xcrack
{
  namespace LevelSetUpdate
  {
    template <int dim>
    BandGrid<dim>::BandGrid(const BoundingBox<dim> &box,
                            const BoundingBox<dim> &body,
                            const double            spacing,
                            const std::size_t       max_points)
    {
      Assert(spacing > 0, ExcInternalError());
      double total = 1;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double length =
            body.get_boundary_points().second[d] - body.lower_bound(d);
          const unsigned int cells =
            std::max(1., std::ceil(length / spacing - 1e-9));
          h[d] = length / cells;
          // The lattice lines of the body's box that bracket the clipped
          // box.
          const double from = std::max(box.lower_bound(d), body.lower_bound(d));
          const double to   = std::min(box.upper_bound(d), body.upper_bound(d));
          const long   first = std::clamp<long>(
            std::floor((from - body.lower_bound(d)) / h[d] + 1e-9), 0, cells);
          const long last = std::clamp<long>(
            std::ceil((to - body.lower_bound(d)) / h[d] - 1e-9), first, cells);
          lower[d]    = body.lower_bound(d) + first * h[d];
          n_points[d] = last - first + 1;
          total *= n_points[d];
        }
      check_input(total <= max_points,
                  "Propagation/Level set update/Upwind/Grid spacing: the "
                  "auxiliary grid over the band would have " +
                    std::to_string(static_cast<std::size_t>(total)) +
                    " points (more than " + std::to_string(max_points) +
                    "); give a larger spacing or a smaller Band radius.");
      std::vector<char> all(static_cast<std::size_t>(total), 1);
      active.resize(all.size());
      set_active(all);
    }



    template <int dim>
    std::size_t
    BandGrid<dim>::size() const
    {
      return active.size();
    }



    template <int dim>
    std::size_t
    BandGrid<dim>::index_of(const std::array<unsigned int, dim> &index) const
    {
      std::size_t i = 0;
      for (int d = dim - 1; d >= 0; --d)
        i = i * n_points[d] + index[d];
      return i;
    }



    template <int dim>
    std::array<unsigned int, dim>
    BandGrid<dim>::coordinates(std::size_t i) const
    {
      std::array<unsigned int, dim> index;
      for (unsigned int d = 0; d < dim; ++d)
        {
          index[d] = i % n_points[d];
          i /= n_points[d];
        }
      return index;
    }



    template <int dim>
    Point<dim>
    BandGrid<dim>::point(const std::size_t i) const
    {
      const std::array<unsigned int, dim> index = coordinates(i);
      Point<dim>                          x     = lower;
      for (unsigned int d = 0; d < dim; ++d)
        x[d] += index[d] * h[d];
      return x;
    }



    template <int dim>
    double
    BandGrid<dim>::spacing(const unsigned int d) const
    {
      return h[d];
    }



    template <int dim>
    double
    BandGrid<dim>::min_spacing() const
    {
      return *std::min_element(h.begin(), h.end());
    }



    template <int dim>
    std::size_t
    BandGrid<dim>::neighbour(const std::size_t  i,
                             const unsigned int d,
                             const unsigned int side) const
    {
      std::size_t stride = 1;
      for (unsigned int e = 0; e < d; ++e)
        stride *= n_points[e];
      const unsigned int k = (i / stride) % n_points[d];
      if ((side == 0 && k == 0) || (side == 1 && k + 1 == n_points[d]))
        return none;
      const std::size_t j = (side == 0 ? i - stride : i + stride);
      return (active[j] ? j : none);
    }



    template <int dim>
    void
    BandGrid<dim>::set_active(const std::vector<char> &flags)
    {
      AssertDimension(flags.size(), active.size());
      active = flags;
      points.clear();
      stencils.clear();
      for (std::size_t i = 0; i < active.size(); ++i)
        if (active[i])
          {
            points.push_back(i);
            std::array<unsigned int, 2 * dim> stencil;
            for (unsigned int d = 0; d < dim; ++d)
              for (unsigned int side = 0; side < 2; ++side)
                {
                  const std::size_t j   = neighbour(i, d, side);
                  stencil[2 * d + side] = (j == none ? missing : j);
                }
            stencils.push_back(stencil);
          }
    }



    template <int dim>
    bool
    BandGrid<dim>::is_active(const std::size_t i) const
    {
      return active[i];
    }



    template <int dim>
    bool
    BandGrid<dim>::is_edge(const std::size_t i) const
    {
      if (!active[i])
        return false;
      for (unsigned int d = 0; d < dim; ++d)
        for (unsigned int side = 0; side < 2; ++side)
          if (neighbour(i, d, side) == none)
            return true;
      return false;
    }



    template <int dim>
    std::size_t
    BandGrid<dim>::n_active() const
    {
      return points.size();
    }



    template <int dim>
    std::pair<std::vector<double>, std::vector<double>>
    BandGrid<dim>::sample(const LevelSetFields<dim> &fields,
                          const unsigned int         crack,
                          const MPI_Comm             communicator) const
    {
      const double              inf = std::numeric_limits<double>::infinity();
      std::vector<double>       lsn(size(), inf), lst(size(), inf);
      const DoFHandler<dim>    &dof_handler = fields.get_dof_handler();
      const FiniteElement<dim> &fe          = dof_handler.get_fe();
      const MappingQ1<dim>      mapping;
      Vector<double>            n_values(fe.n_dofs_per_cell()),
        t_values(fe.n_dofs_per_cell());
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            // The lattice points in the cell's bounding box.
            const BoundingBox<dim>        box = cell->bounding_box();
            std::array<unsigned int, dim> first, last;
            bool                          empty = false;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double from = (box.lower_bound(d) - lower[d]) / h[d];
                const double to   = (box.upper_bound(d) - lower[d]) / h[d];
                if (to < -1e-9 || from > n_points[d] - 1 + 1e-9)
                  {
                    empty = true;
                    break;
                  }
                first[d] = std::max(0., std::ceil(from - 1e-9));
                last[d] =
                  std::min<double>(n_points[d] - 1, std::floor(to + 1e-9));
                empty = empty || first[d] > last[d];
              }
            if (empty)
              continue;
            cell->get_dof_values(fields.lsn(crack), n_values);
            cell->get_dof_values(fields.lst(crack), t_values);
            std::array<unsigned int, dim> index = first;
            while (true)
              {
                const std::size_t i = index_of(index);
                const Point<dim>  x = point(i);
                try
                  {
                    const Point<dim> unit =
                      mapping.transform_real_to_unit_cell(cell, x);
                    if (GeometryInfo<dim>::is_inside_unit_cell(unit, 1e-8))
                      {
                        double n = 0, t = 0;
                        for (unsigned int k = 0; k < fe.n_dofs_per_cell(); ++k)
                          {
                            const double phi = fe.shape_value(k, unit);
                            n += n_values[k] * phi;
                            t += t_values[k] * phi;
                          }
                        lsn[i] = std::min(lsn[i], n);
                        lst[i] = std::min(lst[i], t);
                      }
                  }
                catch (const typename Mapping<dim>::ExcTransformationFailed &)
                  {}
                // The next point of the box, the first direction fastest.
                unsigned int d = 0;
                for (; d < dim; ++d)
                  {
                    if (index[d] < last[d])
                      {
                        ++index[d];
                        break;
                      }
                    index[d] = first[d];
                  }
                if (d == dim)
                  break;
              }
          }
      Utilities::MPI::min(lsn, communicator, lsn);
      Utilities::MPI::min(lst, communicator, lst);
      for (std::size_t i = 0; i < size(); ++i)
        if (lsn[i] == inf)
          lsn[i] = lst[i] = std::numeric_limits<double>::quiet_NaN();
      return {std::move(lsn), std::move(lst)};
    }



    template <int dim>
    std::vector<std::pair<std::size_t, double>>
    BandGrid<dim>::weights(const Point<dim> &x) const
    {
      std::array<unsigned int, dim> base;
      std::array<double, dim>       w;
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double u = (x[d] - lower[d]) / h[d];
          if (u < -1e-9 || u > n_points[d] - 1 + 1e-9)
            return {};
          base[d] = std::min<int>(std::max(0., std::floor(u)), n_points[d] - 2);
          if (n_points[d] == 1)
            base[d] = 0;
          w[d] = std::clamp(u - base[d], 0., 1.);
        }
      std::vector<std::pair<std::size_t, double>> result;
      double                                      sum = 0;
      for (unsigned int corner = 0; corner < (1u << dim); ++corner)
        {
          std::array<unsigned int, dim> index  = base;
          double                        weight = 1;
          bool                          on     = true;
          for (unsigned int d = 0; d < dim; ++d)
            {
              const bool up = corner & (1u << d);
              if (up && n_points[d] == 1)
                on = false;
              index[d] += up;
              weight *= (up ? w[d] : 1 - w[d]);
            }
          if (!on || weight == 0)
            continue;
          const std::size_t i = index_of(index);
          if (!active[i])
            continue;
          result.emplace_back(i, weight);
          sum += weight;
        }
      if (sum < 1e-12)
        return {};
      for (auto &[i, weight] : result)
        weight /= sum;
      return result;
    }



    template class BandGrid<2>;
    template class BandGrid<3>;
  } // namespace LevelSetUpdate
} // namespace xcrack
