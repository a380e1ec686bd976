#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/numerics/rtree.h>

#include <xcrack/fracture/displacement_jump.h>

#include <array>
#include <cmath>

namespace xcrack
{
  template <int dim>
  std::array<double, 3>
  displacement_jump_k(const DoFHandler<dim>               &dof_handler,
                      const GridTools::Cache<dim>         &cache,
                      const TrilinosWrappers::MPI::Vector &solution,
                      const FrontPoint<dim>               &tip,
                      const Material                      &material,
                      const double                         r_min,
                      const double                         r_max,
                      const unsigned int                   n_samples)
  {
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    // K = factor [[u]] / sqrt(r) for modes I, II and III.
    const double factor[3] = {material.mu() / (material.kappa(dim) + 1) *
                                std::sqrt(2 * numbers::PI),
                              material.mu() / (material.kappa(dim) + 1) *
                                std::sqrt(2 * numbers::PI),
                              material.mu() / 4 * std::sqrt(2 * numbers::PI)};
    typename Triangulation<dim>::active_cell_iterator hint;
    const auto                                       &owned_boxes =
      cache.get_locally_owned_cell_bounding_boxes_rtree();
    // The discrete crack may lie off the analytic line by the fit to
    // vertices (up to 1 % of an edge, the crown starting about two cells
    // out): read the sides a hundredth of r_min away and twice that.
    const double side_offset = 1e-2 * r_min;

    // Per sample: the jump (3 components) and whether this rank found both
    // sides (in owned or ghost cells); the first rank that did supplies the
    // value.
    constexpr unsigned int n = 4;
    std::vector<double>    local(n * n_samples, 0.);
    for (unsigned int k = 0; k < n_samples; ++k)
      {
        const double r =
          r_min +
          (r_max - r_min) * (n_samples == 1 ? 0. : double(k) / (n_samples - 1));
        const Point<dim> on_lip = tip.position - r * tip.e1;
        // Samples whose four points lie in no owned cell's box are other
        // ranks' (searching for them here costs a search of the ghost
        // layer); a rank that owns one of them finds the others among its
        // owned and ghost cells, also where the lips run along the border
        // of two ranks' parts.
        Tensor<1, dim> margin;
        for (unsigned int d = 0; d < dim; ++d)
          margin[d] = 2 * side_offset;
        const BoundingBox<dim> sample(
          std::make_pair(on_lip - margin, on_lip + margin));
        if (owned_boxes.qbegin(boost::geometry::index::intersects(sample)) ==
            owned_boxes.qend())
          continue;
        // u at +-side_offset and +-2 side_offset off the lip.
        constexpr std::array<double, 4> offsets = {{1., -1., 2., -2.}};
        Tensor<1, dim>                  u[4];
        bool                            found[4] = {false, false, false, false};
        for (unsigned int side = 0; side < 4; ++side)
          {
            const Point<dim> x = on_lip + offsets[side] * side_offset * tip.e2;
            try
              {
                const auto found_cell =
                  GridTools::find_active_cell_around_point(cache, x, hint);
                // Ghost cells count: the two sides of a lip may belong to
                // different ranks, and the solution is ghosted.
                if (found_cell.first.state() != IteratorState::valid ||
                    found_cell.first->is_artificial())
                  continue;
                hint = found_cell.first;
                const typename DoFHandler<dim>::active_cell_iterator cell(
                  &dof_handler.get_triangulation(),
                  found_cell.first->level(),
                  found_cell.first->index(),
                  &dof_handler);
                FEValues<dim> fe_values(cache.get_mapping(),
                                        cell->get_fe(),
                                        Quadrature<dim>(found_cell.second),
                                        update_values);
                fe_values.reinit(cell);
                std::vector<Vector<double>> value(1, Vector<double>(dim));
                fe_values.get_function_values(solution, value);
                for (unsigned int d = 0; d < dim; ++d)
                  u[side][d] = value[0][d];
                found[side] = true;
              }
            catch (...)
              {
                // Not in this rank's part of the mesh.
              }
          }
        if (found[0] && found[1] && found[2] && found[3])
          {
            // The difference across the lip grows linearly with the offset
            // (the strain along e2): extrapolate it to zero offset.
            const Tensor<1, dim> jump = 2 * (u[0] - u[1]) - (u[2] - u[3]);
            local[n * k]              = jump * tip.e2; // opening
            local[n * k + 1]          = jump * tip.e1; // sliding
            if constexpr (dim == 3)
              local[n * k + 2] = jump * tip.e3; // tearing
            local[n * k + 3] = 1;
          }
      }
    const auto all = Utilities::MPI::all_gather(comm, local);

    // Least-squares line K(r) = K0 + A r for each mode.
    double sr = 0, srr = 0, n_found = 0, sk[3] = {0, 0, 0}, srk[3] = {0, 0, 0};
    for (unsigned int k = 0; k < n_samples; ++k)
      for (const auto &rank : all)
        if (rank[n * k + 3] > 0)
          {
            const double r =
              r_min + (r_max - r_min) *
                        (n_samples == 1 ? 0. : double(k) / (n_samples - 1));
            sr += r;
            srr += r * r;
            n_found += 1;
            for (unsigned int m = 0; m < 3; ++m)
              {
                const double k_m = factor[m] / std::sqrt(r) * rank[n * k + m];
                sk[m] += k_m;
                srk[m] += r * k_m;
              }
            break;
          }
    std::array<double, 3> result = {{0, 0, 0}};
    if (n_found < 2)
      return result;
    const double det = n_found * srr - sr * sr;
    for (unsigned int m = 0; m < 3; ++m)
      result[m] = (srr * sk[m] - sr * srk[m]) / det;
    return result;
  }



  template std::array<double, 3>
  displacement_jump_k<2>(const DoFHandler<2> &,
                         const GridTools::Cache<2> &,
                         const TrilinosWrappers::MPI::Vector &,
                         const FrontPoint<2> &,
                         const Material &,
                         const double,
                         const double,
                         const unsigned int);
  template std::array<double, 3>
  displacement_jump_k<3>(const DoFHandler<3> &,
                         const GridTools::Cache<3> &,
                         const TrilinosWrappers::MPI::Vector &,
                         const FrontPoint<3> &,
                         const Material &,
                         const double,
                         const double,
                         const unsigned int);
} // namespace xcrack
