#include <deal.II/base/quadrature_lib.h>

#include <deal.II/hp/fe_values.h>

#include <xcrack/simulator.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace xcrack
{
  template <int dim>
  std::pair<double, double>
  Simulator<dim>::compute_errors() const
  {
    TimerOutput::Scope t(*timer, "errors");

    const double lambda = material.lambda(dim);
    const double mu     = material.mu();
    const auto   energy = [&](const SymmetricTensor<2, dim> &e) {
      return lambda * trace(e) * trace(e) + 2. * mu * (e * e);
    };

    // Three more points than the assembly rule: the error is then
    // integrated accurately even for Q2 and smooth but oscillating data.
    hp::QCollection<dim> error_quadrature;
    for (unsigned int i = 0; i < fe_collection.size(); ++i)
      error_quadrature.push_back(QGauss<dim>(
        degree + (enrichment && i >= Enrichment<dim>::tip ? 5 : 3)));
    hp::FEValues<dim>                hp_fe_values(fe_collection,
                                   error_quadrature,
                                   update_values | update_gradients |
                                     update_quadrature_points |
                                     update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);

    // [error L2^2, exact L2^2, error energy^2, exact energy^2]
    std::array<double, 4>                    local{{0, 0, 0, 0}};
    std::vector<Tensor<1, dim>>              uh;
    std::vector<SymmetricTensor<2, dim>>     eps_h;
    std::vector<Vector<double>>              u;
    std::vector<std::vector<Tensor<1, dim>>> grad_u;
    SpecialFEValues                          special_values;

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const FEValues<dim> &fe_values =
            reinit_fe_values(cell, hp_fe_values, special_values, degree + 3);
          const unsigned int n_q = fe_values.n_quadrature_points;
          uh.resize(n_q);
          eps_h.resize(n_q);
          u.resize(n_q, Vector<double>(dim));
          grad_u.resize(n_q, std::vector<Tensor<1, dim>>(dim));
          fe_values[displacement].get_function_values(solution, uh);
          fe_values[displacement].get_function_symmetric_gradients(solution,
                                                                   eps_h);
          exact_solution->vector_value_list(fe_values.get_quadrature_points(),
                                            u);
          exact_solution->vector_gradient_list(
            fe_values.get_quadrature_points(), grad_u);

          for (unsigned int q = 0; q < n_q; ++q)
            {
              Tensor<1, dim> exact_u;
              Tensor<2, dim> exact_grad;
              for (unsigned int d = 0; d < dim; ++d)
                {
                  exact_u[d]    = u[q](d);
                  exact_grad[d] = grad_u[q][d];
                }
              const SymmetricTensor<2, dim> exact_eps = symmetrize(exact_grad);
              const double                  JxW       = fe_values.JxW(q);
              local[0] += (exact_u - uh[q]).norm_square() * JxW;
              local[1] += exact_u.norm_square() * JxW;
              local[2] += energy(exact_eps - eps_h[q]) * JxW;
              local[3] += energy(exact_eps) * JxW;
            }
        }

    std::array<double, 4> global;
    Utilities::MPI::sum(ArrayView<const double>(local.data(), 4),
                        mpi_communicator,
                        ArrayView<double>(global.data(), 4));
    const auto relative = [](const double e2, const double u2) {
      return (u2 > 0 ? std::sqrt(e2 / u2) : std::sqrt(e2));
    };
    return {relative(global[0], global[1]), relative(global[2], global[3])};
  }



  template <int dim>
  double
  Simulator<dim>::compute_max_displacement() const
  {
    // Evaluate at the vertices: with enrichment, DoF values are not
    // displacements.
    hp::FEValues<dim>                hp_fe_values(fe_collection,
                                   hp::QCollection<dim>(QTrapezoid<dim>()),
                                   update_values | update_quadrature_points);
    const FEValuesExtractors::Vector displacement(0);
    std::vector<Tensor<1, dim>>      values;
    double                           max_value = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          hp_fe_values.reinit(cell);
          const FEValues<dim> &fe_values = hp_fe_values.get_present_fe_values();
          values.resize(fe_values.n_quadrature_points);
          fe_values[displacement].get_function_values(solution, values);
          for (const auto &u : values)
            for (unsigned int d = 0; d < dim; ++d)
              max_value = std::max(max_value, std::abs(u[d]));
        }
    return Utilities::MPI::max(max_value, mpi_communicator);
  }



  template <int dim>
  void
  Simulator<dim>::report_crack_surface()
  {
    // One line per crack ("crack:" alone, "crack 2:" among several); the
    // statistics add up the measures and keep the largest opening.
    crack_surfaces.resize(cracks.size());
    double measure = 0, front_length = 0, largest_opening = 0;
    for (unsigned int c = 0; c < cracks.size(); ++c)
      {
        CrackSurface<dim> &surface = crack_surfaces[c];
        surface.extract(level_sets, c);
        const double opening = surface.max_opening(dof_handler, solution);
        measure += surface.measure();
        front_length += surface.front_length();
        largest_opening = std::max(largest_opening, opening);

        const std::string name =
          (cracks.size() > 1 ? "crack " + std::to_string(c + 1) : "crack");
        std::ostringstream line;
        line << std::setprecision(6);
        if (dim == 2)
          {
            line << "  " << name << ": length " << surface.measure()
                 << ", tips at";
            for (const auto &front : surface.fronts())
              line << " (" << front[0].position << ")";
          }
        else
          {
            unsigned int n_points = 0;
            for (const auto &front : surface.fronts())
              n_points += front.size();
            line << "  " << name << ": area " << surface.measure()
                 << ", front length " << surface.front_length() << " ("
                 << n_points << " points, " << surface.fronts().size()
                 << (surface.fronts().size() == 1 ? " front)" : " fronts)");
          }
        line << std::scientific << std::setprecision(4) << ", largest opening "
             << opening;
        if (detailed_screen)
          pcout << line.str() << std::endl;
      }
    statistics.add_value("crack_size", measure);
    statistics.add_value("front_length", front_length);
    statistics.add_value("max_opening", largest_opening);
  }



  template <int dim>
  void
  Simulator<dim>::print_convergence_table() const
  {
    pcout << std::endl
          << "Convergence (rates against the mean cell size h = cells^(-1/"
          << dim << "))" << std::endl
          << " mesh     cells      dofs   L2_error  rate  energy_error  rate"
          << std::endl;
    for (unsigned int r = 0; r < statistics.n_rows(); ++r)
      {
        const auto value = [&](const char *c) { return statistics.get(c, r); };
        pcout << std::setw(5) << r << std::setw(10)
              << static_cast<long long>(value("cells")) << std::setw(10)
              << static_cast<long long>(value("dofs")) << std::scientific
              << std::setprecision(3) << std::setw(11) << value("L2_error");
        const auto rate = [&](const char *c) {
          // No rate without a previous mesh, or when the mesh did not
          // change (a strategy at its maximum level).
          if (r == 0 || value("cells") == statistics.get("cells", r - 1))
            return std::string("    -");
          const double h_ratio =
            std::pow(value("cells") / statistics.get("cells", r - 1), 1. / dim);
          std::ostringstream s;
          s << std::fixed << std::setprecision(2) << std::setw(6)
            << std::log(statistics.get(c, r - 1) / value(c)) /
                 std::log(h_ratio);
          return s.str();
        };
        pcout << rate("L2_error") << std::setw(14) << value("energy_error")
              << rate("energy_error") << std::defaultfloat << std::endl;
      }
  }


  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
