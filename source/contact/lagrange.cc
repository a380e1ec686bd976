#include <deal.II/base/mpi.h>

#include <xcrack/contact/lagrange.h>
#include <xcrack/input_error.h>
#include <xcrack/material.h>
#include <xcrack/xfem/enrichment.h>
#include <xcrack/xfem/lip_values.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace xcrack
{
  namespace Contact
  {
    template <int dim>
    void
    Lagrange<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Lagrange");
      prm.declare_entry(
        "Multiplier space",
        "vital nodes",
        Patterns::Selection(MultiplierSpace<dim>::names()),
        "The space of the contact pressure on the lips. vital nodes: the "
        "crossings of the lips with the edges share a multiplier with the "
        "other crossings of the nearer vertex of their edge (stable); "
        "edges: a multiplier per crossing (the naive space, whose pressures "
        "oscillate where the crack passes near a vertex); cells: one "
        "pressure per cell with lips.");
      prm.declare_entry("Complementarity coefficient",
                        "1",
                        Patterns::Double(),
                        "c of the active set: a multiplier is active (its "
                        "lips closed) where lambda - c (E / h) g > 0, g its "
                        "mean gap (> 0). It weighs a gap against a pressure "
                        "when the set is updated and does not change the "
                        "solution.");
      prm.leave_subsection();
    }



    template <int dim>
    void
    Lagrange<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Lagrange");
      space = MultiplierSpace<dim>(
        MultiplierSpace<dim>::parse(prm.get("Multiplier space")));
      complementarity = prm.get_double("Complementarity coefficient");
      check_input(complementarity > 0,
                  "Contact/Lagrange/Complementarity coefficient = " +
                    prm.get("Complementarity coefficient") +
                    ": must be positive.");
    }



    template <int dim>
    void
    Lagrange<dim>::initialize()
    {
      check_input(!this->get_enrichment() ||
                    !this->get_enrichment()->get_parameters().gather,
                  "Contact/Formulation = lagrange with Enrichment/Gather tip "
                  "DoFs = true: the few gathered branch unknowns carry the "
                  "jump of the whole tip zone, and the multipliers there "
                  "cannot all be met (the pressures would not be stable); "
                  "set Gather tip DoFs = false, or use Formulation = "
                  "penalty.");
    }



    template <int dim>
    void
    Lagrange<dim>::setup_own_unknowns()
    {
      const Enrichment<dim> &enrichment = *this->get_enrichment();
      const MPI_Comm         comm       = this->get_mpi_communicator();
      space.reinit(this->get_dof_handler(), enrichment, comm);
      const unsigned int n = space.size();
      lambda.assign(n, 0.);
      gap.assign(n, 0.);
      mass.assign(n, 0.);
      stiffness.assign(n, 0.);
      active.assign(n, 1);
      std::vector<double> coupling(n, 0.);
      cells.clear();

      LipValues<dim> lips(enrichment);
      const double   youngs_modulus = this->get_material().youngs_modulus;
      for (const auto &cell : this->get_dof_handler().active_cell_iterators())
        {
          if (!cell->is_locally_owned())
            continue;
          const auto *basis = space.basis(cell->id());
          if (basis == nullptr)
            continue;
          const unsigned int n_points = lips.reinit(cell);
          AssertDimension(n_points, basis->values.size());
          const unsigned int n_dofs = cell->get_fe().n_dofs_per_cell();
          const unsigned int m      = basis->multipliers.size();
          CellData          &data   = cells[cell->id()];
          data.cell                 = cell;
          data.multipliers          = basis->multipliers;
          data.psi                  = basis->values;
          data.coupling.reinit(m, n_dofs);
          data.gap_rows.reinit(n_points, n_dofs);
          data.mass.assign(m, 0.);
          data.gaps.assign(n_points, 0.);
          data.stiffness = youngs_modulus *
                           std::sqrt(static_cast<double>(dim)) /
                           cell->diameter();
          for (unsigned int q = 0; q < n_points; ++q)
            {
              const double ds = lips.normal_ds(q).norm();
              data.normals.push_back(lips.crack_normal(q));
              data.ds.push_back(ds);
              data.points.push_back(lips.point(q));
              for (unsigned int i = 0; i < n_dofs; ++i)
                data.gap_rows(q, i) =
                  data.normals[q][lips.component(i)] * lips.jump(i, q);
              for (unsigned int j = 0; j < m; ++j)
                {
                  const double w = data.psi[q][j] * ds;
                  data.mass[j] += w;
                  for (unsigned int i = 0; i < n_dofs; ++i)
                    data.coupling(j, i) += w * data.gap_rows(q, i);
                }
            }
          for (unsigned int j = 0; j < m; ++j)
            {
              mass[data.multipliers[j]] += data.mass[j];
              stiffness[data.multipliers[j]] += data.mass[j] * data.stiffness;
              for (unsigned int i = 0; i < n_dofs; ++i)
                coupling[data.multipliers[j]] += std::abs(data.coupling(j, i));
            }
        }
      Utilities::MPI::sum(mass, comm, mass);
      Utilities::MPI::sum(stiffness, comm, stiffness);
      Utilities::MPI::sum(coupling, comm, coupling);
      coupled.assign(n, 0);
      for (unsigned int k = 0; k < n; ++k)
        {
          stiffness[k] = (mass[k] > 0 ? stiffness[k] / mass[k] : 0.);
          coupled[k]   = (mass[k] > 0 && coupling[k] > 0);
        }
    }



    template <int dim>
    void
    Lagrange<dim>::start_assembly(const bool first)
    {
      n_changed = 0;
      if (first)
        {
          // Closed everywhere: the first iterate is zero.
          active = coupled;
          std::fill(lambda.begin(), lambda.end(), 0.);
          return;
        }
      // The weighted gaps of the current iterate, and its gap at each lip
      // point (for the output).
      std::fill(gap.begin(), gap.end(), 0.);
      Vector<double> u;
      for (auto &[id, data] : cells)
        {
          u.reinit(data.cell->get_fe().n_dofs_per_cell());
          data.cell->get_dof_values(this->get_solution(), u);
          for (unsigned int j = 0; j < data.multipliers.size(); ++j)
            {
              double g = 0;
              for (unsigned int i = 0; i < u.size(); ++i)
                g += data.coupling(j, i) * u[i];
              gap[data.multipliers[j]] += g;
            }
          for (unsigned int q = 0; q < data.points.size(); ++q)
            {
              data.gaps[q] = 0;
              for (unsigned int i = 0; i < u.size(); ++i)
                data.gaps[q] += data.gap_rows(q, i) * u[i];
            }
        }
      const MPI_Comm comm = this->get_mpi_communicator();
      Utilities::MPI::sum(gap, comm, gap);
      // The active set of the iterate (every rank alike); the changes are
      // counted by the owner of each multiplier.
      const auto [begin, end] = space.owned_range();
      for (unsigned int k = 0; k < lambda.size(); ++k)
        {
          const char now =
            (coupled[k] &&
             lambda[k] - complementarity * stiffness[k] * gap[k] / mass[k] > 0);
          if (now != active[k] && k >= begin && k < end)
            {
              if (n_changed == 0)
                first_changed = space.location(k);
              ++n_changed;
            }
          active[k] = now;
        }
    }



    template <int dim>
    void
    Lagrange<dim>::assemble(const Assembly::CellInput<dim> &,
                            FullMatrix<double> &,
                            Vector<double> &,
                            std::string &)
    {}



    template <int dim>
    std::vector<unsigned int>
    Lagrange<dim>::own_unknowns_of(
      const typename DoFHandler<dim>::active_cell_iterator &cell) const
    {
      const auto it = cells.find(cell->id());
      return (it == cells.end() ? std::vector<unsigned int>() :
                                  it->second.multipliers);
    }



    template <int dim>
    void
    Lagrange<dim>::assemble_own(const Assembly::CellInput<dim> &input,
                                const unsigned int              n_dofs,
                                FullMatrix<double>             &matrix,
                                Vector<double> &)
    {
      const CellData &data = cells.at(input.cell->id());
      for (unsigned int j = 0; j < data.multipliers.size(); ++j)
        {
          const unsigned int row = n_dofs + j;
          if (active[data.multipliers[j]])
            // The gap held at zero, and the pressure's force on the lips.
            for (unsigned int i = 0; i < n_dofs; ++i)
              {
                matrix(row, i) -= data.coupling(j, i);
                matrix(i, row) -= data.coupling(j, i);
              }
          else
            // Open: lambda = 0, scaled like the rows of the constraint.
            matrix(row, row) -= data.mass[j] / data.stiffness;
        }
    }



    template <int dim>
    void
    Lagrange<dim>::set_own_values(const std::vector<double> &values)
    {
      AssertDimension(values.size(), lambda.size());
      lambda = values;
    }



    template <int dim>
    std::pair<unsigned int, std::string>
    Lagrange<dim>::changed_statuses() const
    {
      std::ostringstream where;
      if (n_changed > 0)
        where << "the first at (" << first_changed << ")";
      return {n_changed, where.str()};
    }



    template <int dim>
    unsigned int
    Lagrange<dim>::n_own_unknowns() const
    {
      return space.size();
    }



    template <int dim>
    std::pair<unsigned int, unsigned int>
    Lagrange<dim>::owned_own_unknowns() const
    {
      return space.owned_range();
    }



    template <int dim>
    double
    Lagrange<dim>::pressure(const CellData &data, const unsigned int q) const
    {
      double p = 0;
      for (unsigned int j = 0; j < data.multipliers.size(); ++j)
        p += data.psi[q][j] * lambda[data.multipliers[j]];
      return p;
    }



    template <int dim>
    Tensor<1, dim>
    Lagrange<dim>::lip_traction(const CellId &cell, const unsigned int q) const
    {
      const auto it = cells.find(cell);
      if (it == cells.end() || q >= it->second.points.size())
        return Tensor<1, dim>();
      return pressure(it->second, q) * it->second.normals[q];
    }



    template <int dim>
    typename Interface<dim>::LipState
    Lagrange<dim>::lip_state(const CellId &cell) const
    {
      typename Interface<dim>::LipState state;
      const auto                        it = cells.find(cell);
      if (it == cells.end())
        return state;
      const CellData &data   = it->second;
      double          length = 0;
      for (unsigned int q = 0; q < data.points.size(); ++q)
        {
          const double p = pressure(data, q);
          length += data.ds[q];
          state.pressure += p * data.ds[q];
          state.gap += data.gaps[q] * data.ds[q];
          state.traction += p * data.normals[q] * data.ds[q];
          state.closed += (p > 0 ? data.ds[q] : 0.);
        }
      if (length > 0)
        {
          state.pressure /= length;
          state.gap /= length;
          state.traction /= length;
          state.closed /= length;
        }
      return state;
    }



    template <int dim>
    double
    Lagrange<dim>::closed_fraction(const Point<dim> &x,
                                   const double      radius) const
    {
      double near = 0, closed = 0;
      for (const auto &[id, data] : cells)
        for (unsigned int q = 0; q < data.points.size(); ++q)
          if (data.points[q].distance(x) < radius)
            {
              near += data.ds[q];
              closed += (pressure(data, q) > 0 ? data.ds[q] : 0.);
            }
      const MPI_Comm comm = this->get_mpi_communicator();
      near                = Utilities::MPI::sum(near, comm);
      closed              = Utilities::MPI::sum(closed, comm);
      return (near > 0 ? closed / near : 0.);
    }



    template <int dim>
    std::map<std::string, double>
    Lagrange<dim>::statistics() const
    {
      double lips = 0, closed = 0;
      double low = std::numeric_limits<double>::max(), high = 0;
      for (const auto &[id, data] : cells)
        for (unsigned int q = 0; q < data.points.size(); ++q)
          {
            const double p = pressure(data, q);
            lips += data.ds[q];
            if (p > 0)
              {
                closed += data.ds[q];
                low  = std::min(low, p);
                high = std::max(high, p);
              }
          }
      // The gap held where closed: the weighted gap of each active
      // multiplier over its mass (zero to round-off at convergence).
      double gap_min = 0;
      for (unsigned int k = 0; k < lambda.size(); ++k)
        if (active[k] && mass[k] > 0)
          gap_min = std::min(gap_min, gap[k] / mass[k]);
      const MPI_Comm comm = this->get_mpi_communicator();
      lips                = Utilities::MPI::sum(lips, comm);
      closed              = Utilities::MPI::sum(closed, comm);
      low                 = Utilities::MPI::min(low, comm);
      high                = Utilities::MPI::max(high, comm);
      return {{"contact_closed", lips > 0 ? closed / lips : 0.},
              {"contact_pressure_min", closed > 0 ? low : 0.},
              {"contact_pressure_max", high},
              {"contact_gap_min", gap_min},
              {"contact_multipliers", static_cast<double>(lambda.size())}};
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Lagrange,
                           "lagrange",
                           "the contact pressure as Lagrange multipliers on "
                           "a stable space of the lips, which hold the lips "
                           "exactly (subsection Lagrange; symmetric "
                           "indefinite systems: Linear solver/Type = "
                           "direct).")
  } // namespace Contact
} // namespace xcrack
