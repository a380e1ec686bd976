#include <deal.II/base/mpi.h>

#include <xcrack/contact/penalty.h>
#include <xcrack/input_error.h>
#include <xcrack/material.h>

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
    Penalty<dim>::declare_parameters(ParameterHandler &prm)
    {
      prm.enter_subsection("Penalty");
      prm.declare_entry(
        "Pressure space",
        "cells",
        Patterns::Selection("lip points|cells"),
        "Where the gap is penalised: at every point of the lips' quadrature "
        "(the pressures oscillate from point to point where many points "
        "hold the few jump unknowns of a cell: the naive space), or its "
        "mean over each cell's lips (one pressure per cell).");
      prm.declare_entry("Penalty coefficient",
                        "1000",
                        Patterns::Double(),
                        "kappa = coefficient E / h (h: the cell's size): how "
                        "much stiffer than a cell's worth of material the "
                        "springs between closed lips are (> 0). The lips "
                        "interpenetrate by about p h / (coefficient E).");
      prm.leave_subsection();
    }



    template <int dim>
    void
    Penalty<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Penalty");
      coefficient = prm.get_double("Penalty coefficient");
      per_cell    = (prm.get("Pressure space") == "cells");
      check_input(coefficient > 0,
                  "Contact/Penalty/Penalty coefficient = " +
                    prm.get("Penalty coefficient") + ": must be positive.");
    }



    template <int dim>
    void
    Penalty<dim>::start_assembly(const bool first)
    {
      if (!lip_values)
        lip_values = std::make_unique<LipValues<dim>>(*this->get_enrichment());
      // A solve starts open everywhere (its first iterate is zero).
      if (first)
        {
          closed.clear();
          pressures.clear();
          normals.clear();
        }
      n_changed = 0;
      lip_points.clear();
      lip_measure    = 0;
      closed_measure = 0;
      pressure_min   = std::numeric_limits<double>::max();
      pressure_max   = 0;
    }



    template <int dim>
    void
    Penalty<dim>::assemble(const Assembly::CellInput<dim> &input,
                           FullMatrix<double>             &matrix,
                           Vector<double> &,
                           std::string &)
    {
      const unsigned int n_points = lip_values->reinit(input.cell);
      if (n_points == 0)
        return;
      const double h =
        input.cell->diameter() / std::sqrt(static_cast<double>(dim));
      const double kappa =
        coefficient * this->get_material().youngs_modulus / h;
      const unsigned int n_dofs = matrix.m();

      const CellId id = input.cell->id();
      // The pressure's space: one value per lip point, or one per cell (the
      // mean gap of the cell's lips).
      const unsigned int n_groups = (per_cell ? 1 : n_points);
      std::vector<char> &status   = closed[id];
      // The statuses this iterate was solved with (none before a solve's
      // first step).
      const bool known = (status.size() == n_groups);
      status.resize(n_groups);
      std::vector<double>         &p = pressures[id];
      std::vector<Tensor<1, dim>> &n = normals[id];
      p.resize(n_points);
      n.resize(n_points);
      std::vector<double> mean_jump(n_dofs);
      for (unsigned int group = 0; group < n_groups; ++group)
        {
          const unsigned int first = (per_cell ? 0 : group);
          const unsigned int last  = (per_cell ? n_points : group + 1);
          // The group's length (area) and the mean of n . [[phi_i]].
          double length = 0;
          std::fill(mean_jump.begin(), mean_jump.end(), 0.);
          for (unsigned int q = first; q < last; ++q)
            {
              const double ds = lip_values->normal_ds(q).norm();
              n[q]            = lip_values->normal_ds(q) / ds;
              length += ds;
              for (unsigned int i = 0; i < n_dofs; ++i)
                mean_jump[i] +=
                  n[q][lip_values->component(i)] * lip_values->jump(i, q) * ds;
            }
          if (length == 0)
            continue;
          double gap = 0;
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              mean_jump[i] /= length;
              // Zero at the first step: the lips start closed, so that a
              // piece the crack cuts off rests on them from the start
              // (open, it would float and the first system be singular).
              if (input.iterate)
                gap += (*input.iterate)[i] * mean_jump[i];
            }
          const bool is_closed = (gap <= 0);
          if (known && is_closed != bool(status[group]))
            {
              if (n_changed == 0)
                first_changed = lip_values->point(first);
              ++n_changed;
            }
          status[group] = is_closed;
          for (unsigned int q = first; q < last; ++q)
            p[q] = (is_closed ? -kappa * gap : 0.);
          if (!is_closed)
            continue;
          for (unsigned int i = 0; i < n_dofs; ++i)
            if (mean_jump[i] != 0)
              for (unsigned int j = 0; j < n_dofs; ++j)
                matrix(i, j) += kappa * length * mean_jump[i] * mean_jump[j];
        }
      for (unsigned int q = 0; q < n_points; ++q)
        {
          const double ds = lip_values->normal_ds(q).norm();
          lip_measure += ds;
          lip_points.push_back(
            {lip_values->point(q), ds, bool(status[per_cell ? 0 : q])});
          if (status[per_cell ? 0 : q])
            {
              closed_measure += ds;
              pressure_min = std::min(pressure_min, p[q]);
              pressure_max = std::max(pressure_max, p[q]);
            }
        }
    }



    template <int dim>
    std::pair<unsigned int, std::string>
    Penalty<dim>::changed_statuses() const
    {
      std::ostringstream where;
      if (n_changed > 0)
        where << "the first at (" << first_changed << ")";
      return {n_changed, where.str()};
    }



    template <int dim>
    std::map<std::string, double>
    Penalty<dim>::statistics() const
    {
      const MPI_Comm comm   = this->get_mpi_communicator();
      const double   lips   = Utilities::MPI::sum(lip_measure, comm);
      const double   closed = Utilities::MPI::sum(closed_measure, comm);
      const double   low    = Utilities::MPI::min(pressure_min, comm);
      const double   high   = Utilities::MPI::max(pressure_max, comm);
      // The largest interpenetration is that of the largest pressure.
      return {{"contact_closed", lips > 0 ? closed / lips : 0.},
              {"contact_pressure_min", closed > 0 ? low : 0.},
              {"contact_pressure_max", high}};
    }



    template <int dim>
    double
    Penalty<dim>::closed_fraction(const Point<dim> &x,
                                  const double      radius) const
    {
      double near = 0, closed = 0;
      for (const LipPoint &p : lip_points)
        if (p.x.distance(x) < radius)
          {
            near += p.ds;
            closed += (p.closed ? p.ds : 0.);
          }
      const MPI_Comm comm = this->get_mpi_communicator();
      near                = Utilities::MPI::sum(near, comm);
      closed              = Utilities::MPI::sum(closed, comm);
      return (near > 0 ? closed / near : 0.);
    }



    template <int dim>
    Tensor<1, dim>
    Penalty<dim>::lip_traction(const CellId &cell, const unsigned int q) const
    {
      const auto it = pressures.find(cell);
      if (it == pressures.end() || q >= it->second.size())
        return Tensor<1, dim>();
      return it->second[q] * normals.at(cell)[q];
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Penalty,
                           "penalty",
                           "closed lips press on each other with kappa "
                           "times their interpenetration (subsection "
                           "Penalty).")
  } // namespace Contact
} // namespace xcrack
