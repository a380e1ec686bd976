#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/grid/grid_tools_cache.h>
#include <deal.II/numerics/rtree.h>

#include <xcrack/fracture/displacement_jump.h>
#include <xcrack/xfem/enrichment.h>

#include <array>
#include <cmath>
#include <limits>

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
                      const Enrichment<dim>               *enrichment,
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
    // The DoF cell of a cell that find_active_cell_around_point() gave.
    const auto dof_cell = [&](const auto &tria_cell) {
      return typename DoFHandler<dim>::active_cell_iterator(
        &dof_handler.get_triangulation(),
        tria_cell->level(),
        tria_cell->index(),
        &dof_handler);
    };
    // The owned or ghost cell around @p x and @p x in its reference cell
    // (an invalid iterator if this rank does not hold it).
    const auto cell_around = [&](const Point<dim> &x) {
      std::pair<typename DoFHandler<dim>::active_cell_iterator, Point<dim>>
        found;
      try
        {
          const auto around =
            GridTools::find_active_cell_around_point(cache, x, hint);
          if (around.first.state() == IteratorState::valid &&
              !around.first->is_artificial())
            {
              hint  = around.first;
              found = {dof_cell(around.first), around.second};
            }
        }
      catch (...)
        {
          // Not in this rank's part of the mesh.
        }
      return found;
    };

    for (unsigned int k = 0; k < n_samples; ++k)
      {
        const double r =
          r_min +
          (r_max - r_min) * (n_samples == 1 ? 0. : double(k) / (n_samples - 1));
        Point<dim> on_lip = tip.position - r * tip.e1;
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
        // The lips' own frame at the sample: normal e2 and sliding
        // direction e1 of the tip unless the lips are followed.
        Tensor<1, dim> normal = tip.e2, sliding = tip.e1, tearing;
        if constexpr (dim == 3)
          tearing = tip.e3;
        if (enrichment)
          {
            // A crack that kinked or curves behind its tip leaves the
            // straight line: move the sample onto the discrete lip (the
            // zero of the cell's lsn, fitted to vertices) along grad lsn,
            // and take the frame of the lip there.
            bool on_crack = false;
            for (unsigned int iteration = 0; iteration < 4; ++iteration)
              {
                const auto [cell, xi] = cell_around(on_lip);
                (void)xi;
                if (cell.state() != IteratorState::valid ||
                    cell->active_fe_index() == Enrichment<dim>::plain)
                  break;
                const LevelSetFunctions<dim> &crack =
                  enrichment->crack_of(cell);
                const double         value    = crack.lsn(on_lip);
                const Tensor<1, dim> gradient = crack.gradients(on_lip).first;
                if (!(gradient.norm() > 0))
                  break;
                normal = gradient / gradient.norm();
                if (std::abs(value) <= 1e-8 * r_min)
                  {
                    on_crack = (crack.lst(on_lip) < 0);
                    break;
                  }
                on_lip -= value / gradient.norm_square() * gradient;
              }
            // A lip that does not reach this far behind the tip (a short
            // crack): no sample here.
            if (!on_crack)
              continue;
            if (normal * tip.e2 < 0)
              normal = -normal;
            // Nor beyond a kink: there the lips are not those of the tip's
            // Williams field (a lip turned by more than 10 degrees from the
            // tip's plane).
            if (normal * tip.e2 < std::cos(10. * numbers::PI / 180.))
              continue;
            sliding = tip.e1 - (tip.e1 * normal) * normal;
            sliding /= sliding.norm();
            if constexpr (dim == 3)
              tearing = cross_product_3d(sliding, normal);
          }
        // u at +-side_offset and +-2 side_offset off the lip.
        constexpr std::array<double, 4> offsets = {{1., -1., 2., -2.}};
        Tensor<1, dim>                  u[4];
        bool                            found[4] = {false, false, false, false};
        for (unsigned int side = 0; side < 4; ++side)
          {
            const Point<dim> x = on_lip + offsets[side] * side_offset * normal;
            const auto [cell, xi] = cell_around(x);
            // Ghost cells count: the two sides of a lip may belong to
            // different ranks, and the solution is ghosted.
            if (cell.state() != IteratorState::valid)
              continue;
            FEValues<dim> fe_values(cache.get_mapping(),
                                    cell->get_fe(),
                                    Quadrature<dim>(xi),
                                    update_values);
            fe_values.reinit(cell);
            std::vector<Vector<double>> value(1, Vector<double>(dim));
            fe_values.get_function_values(solution, value);
            for (unsigned int d = 0; d < dim; ++d)
              u[side][d] = value[0][d];
            found[side] = true;
          }
        if (found[0] && found[1] && found[2] && found[3])
          {
            // The difference across the lip grows linearly with the offset
            // (the strain along e2): extrapolate it to zero offset.
            const Tensor<1, dim> jump = 2 * (u[0] - u[1]) - (u[2] - u[3]);
            local[n * k]              = jump * normal;  // opening
            local[n * k + 1]          = jump * sliding; // sliding
            if constexpr (dim == 3)
              local[n * k + 2] = jump * tearing; // tearing
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
    // Fewer than half the samples on the lips: no estimate.
    std::array<double, 3> result = {{std::numeric_limits<double>::quiet_NaN(),
                                     std::numeric_limits<double>::quiet_NaN(),
                                     std::numeric_limits<double>::quiet_NaN()}};
    if (2 * n_found < n_samples || n_found < 2)
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
                         const Enrichment<2> *,
                         const unsigned int);
  template std::array<double, 3>
  displacement_jump_k<3>(const DoFHandler<3> &,
                         const GridTools::Cache<3> &,
                         const TrilinosWrappers::MPI::Vector &,
                         const FrontPoint<3> &,
                         const Material &,
                         const double,
                         const double,
                         const Enrichment<3> *,
                         const unsigned int);
} // namespace xcrack
