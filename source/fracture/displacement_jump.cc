#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q1.h>

#include <xcrack/fracture/displacement_jump.h>

#include <cmath>

namespace xcrack
{
  template <int dim>
  std::array<double, 2>
  displacement_jump_k(const DoFHandler<dim>               &dof_handler,
                      const TrilinosWrappers::MPI::Vector &solution,
                      const FrontPoint<dim>               &tip,
                      const Material                      &material,
                      const double                         r_min,
                      const double                         r_max,
                      const unsigned int                   n_samples)
  {
    const MPI_Comm comm = dof_handler.get_triangulation().get_communicator();
    const MappingQ1<dim> mapping;
    const double         factor =
      material.mu() / (material.kappa(dim) + 1) * std::sqrt(2 * numbers::PI);

    // Per sample: the jump (2 components) and whether this rank found both
    // sides; the first rank that did supplies the value.
    std::vector<double> local(3 * n_samples, 0.);
    for (unsigned int k = 0; k < n_samples; ++k)
      {
        const double r =
          r_min +
          (r_max - r_min) * (n_samples == 1 ? 0. : double(k) / (n_samples - 1));
        const Point<dim> on_lip = tip.position - r * tip.e1;
        Tensor<1, dim>   u[2];
        bool             found[2] = {false, false};
        for (unsigned int side = 0; side < 2; ++side)
          {
            const Point<dim> x =
              on_lip + (side == 0 ? 1. : -1.) * 1e-8 * r * tip.e2;
            for (const auto &cell : dof_handler.active_cell_iterators())
              if (cell->is_locally_owned() && cell->point_inside(x))
                {
                  const Point<dim> xi =
                    mapping.transform_real_to_unit_cell(cell, x);
                  FEValues<dim> fe_values(mapping,
                                          cell->get_fe(),
                                          Quadrature<dim>(xi),
                                          update_values);
                  fe_values.reinit(cell);
                  std::vector<Vector<double>> value(1, Vector<double>(dim));
                  fe_values.get_function_values(solution, value);
                  for (unsigned int d = 0; d < dim; ++d)
                    u[side][d] = value[0][d];
                  found[side] = true;
                  break;
                }
          }
        if (found[0] && found[1])
          {
            const Tensor<1, dim> jump = u[0] - u[1];
            local[3 * k]              = jump * tip.e2; // opening
            local[3 * k + 1]          = jump * tip.e1; // sliding
            local[3 * k + 2]          = 1;
          }
      }
    const auto all = Utilities::MPI::all_gather(comm, local);

    // Least-squares line K(r) = K0 + A r for each mode.
    double sr = 0, srr = 0, n = 0, sk[2] = {0, 0}, srk[2] = {0, 0};
    for (unsigned int k = 0; k < n_samples; ++k)
      for (const auto &rank : all)
        if (rank[3 * k + 2] > 0)
          {
            const double r =
              r_min + (r_max - r_min) *
                        (n_samples == 1 ? 0. : double(k) / (n_samples - 1));
            const double scale = factor / std::sqrt(r);
            const double k_I   = scale * rank[3 * k],
                         k_II  = scale * rank[3 * k + 1];
            sr += r;
            srr += r * r;
            n += 1;
            sk[0] += k_I;
            sk[1] += k_II;
            srk[0] += r * k_I;
            srk[1] += r * k_II;
            break;
          }
    std::array<double, 2> result = {{0, 0}};
    if (n < 2)
      return result;
    const double det = n * srr - sr * sr;
    for (unsigned int m = 0; m < 2; ++m)
      result[m] = (srr * sk[m] - sr * srk[m]) / det;
    return result;
  }



  template std::array<double, 2>
  displacement_jump_k<2>(const DoFHandler<2> &,
                         const TrilinosWrappers::MPI::Vector &,
                         const FrontPoint<2> &,
                         const Material &,
                         const double,
                         const double,
                         const unsigned int);
} // namespace xcrack
