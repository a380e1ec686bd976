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
      prm.declare_entry("Tangential penalty coefficient",
                        "1000",
                        Patterns::Double(),
                        "With friction: kappa_T = coefficient E / h, the "
                        "stiffness of the springs that hold sticking lips "
                        "(> 0). Sticking lips slip by about t h / "
                        "(coefficient E), t their tangential traction.");
      prm.leave_subsection();
    }



    template <int dim>
    void
    Penalty<dim>::parse_parameters(ParameterHandler &prm)
    {
      const Plugins::ScopedSubsection scope(prm, "Penalty");
      coefficient            = prm.get_double("Penalty coefficient");
      tangential_coefficient = prm.get_double("Tangential penalty coefficient");
      per_cell               = (prm.get("Pressure space") == "cells");
      check_input(coefficient > 0,
                  "Contact/Penalty/Penalty coefficient = " +
                    prm.get("Penalty coefficient") + ": must be positive.");
      check_input(tangential_coefficient > 0,
                  "Contact/Penalty/Tangential penalty coefficient = " +
                    prm.get("Tangential penalty coefficient") +
                    ": must be positive.");
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
          statuses.clear();
          pressures.clear();
          tractions.clear();
          cell_states.clear();
        }
      n_changed = 0;
      lip_points.clear();
      lip_measure    = 0;
      closed_measure = 0;
      slip_measure   = 0;
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
      std::vector<char> &status   = statuses[id];
      // The statuses this iterate was solved with (none before a solve's
      // first step).
      const bool known = (status.size() == n_groups);
      status.resize(n_groups);
      std::vector<double>         &p = pressures[id];
      std::vector<Tensor<1, dim>> &t = tractions[id];
      p.resize(n_points);
      t.resize(n_points);
      const bool                  friction = (this->friction > 0);
      std::vector<double>         mean_gap(n_dofs);
      std::vector<Tensor<1, dim>> mean_slip(friction ? n_dofs : 0);
      std::vector<Tensor<1, dim>> n(n_points);
      // The cell's means, for the output.
      typename Interface<dim>::LipState &state = cell_states[id];
      state                                    = {};
      for (unsigned int group = 0; group < n_groups; ++group)
        {
          const unsigned int first = (per_cell ? 0 : group);
          const unsigned int last  = (per_cell ? n_points : group + 1);
          // The group's length (area), and the means over it of n . [[phi_i]]
          // and, with friction, of P_T [[phi_i]].
          double length = 0;
          std::fill(mean_gap.begin(), mean_gap.end(), 0.);
          std::fill(mean_slip.begin(), mean_slip.end(), Tensor<1, dim>());
          for (unsigned int q = first; q < last; ++q)
            {
              const double ds = lip_values->normal_ds(q).norm();
              n[q]            = lip_values->normal_ds(q) / ds;
              length += ds;
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  const double       jump_ds = lip_values->jump(i, q) * ds;
                  const unsigned int c       = lip_values->component(i);
                  mean_gap[i] += n[q][c] * jump_ds;
                  if (friction && jump_ds != 0)
                    {
                      mean_slip[i] -= (n[q][c] * jump_ds) * n[q];
                      mean_slip[i][c] += jump_ds;
                    }
                }
            }
          if (length == 0)
            continue;
          // Zero at the first step: the lips start closed and sticking, so
          // that a piece the crack cuts off rests on them from the start
          // (open, it would float and the first system be singular).
          double         gap = 0;
          Tensor<1, dim> slip;
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              mean_gap[i] /= length;
              if (friction)
                mean_slip[i] /= length;
              if (input.iterate)
                {
                  gap += (*input.iterate)[i] * mean_gap[i];
                  if (friction)
                    slip += (*input.iterate)[i] * mean_slip[i];
                }
            }
          const double   pressure = (gap <= 0 ? -kappa * gap : 0.);
          Tensor<1, dim> tangential;
          bool           sliding = false;
          if (gap <= 0)
            {
              for (unsigned int i = 0; i < n_dofs; ++i)
                if (mean_gap[i] != 0)
                  for (unsigned int j = 0; j < n_dofs; ++j)
                    matrix(i, j) += kappa * length * mean_gap[i] * mean_gap[j];
              if (friction)
                tangential =
                  add_friction(slip,
                               mean_slip,
                               mean_gap,
                               pressure,
                               kappa,
                               tangential_coefficient * kappa / coefficient,
                               length,
                               matrix,
                               sliding);
            }
          const char now = (gap > 0 ? opened : sliding ? slipping : sticking);
          if (known && now != status[group])
            {
              if (n_changed == 0)
                first_changed = lip_values->point(first);
              ++n_changed;
            }
          status[group] = now;
          for (unsigned int q = first; q < last; ++q)
            {
              p[q] = pressure;
              t[q] = pressure * n[q] + tangential;
              state.gap += gap * lip_values->normal_ds(q).norm();
            }
        }
      double cell_measure = 0;
      for (unsigned int q = 0; q < n_points; ++q)
        {
          const double ds  = lip_values->normal_ds(q).norm();
          const char   now = status[per_cell ? 0 : q];
          cell_measure += ds;
          state.pressure += p[q] * ds;
          state.traction += t[q] * ds;
          state.closed += (now != opened ? ds : 0.);
          state.slipping += (now == slipping ? ds : 0.);
          lip_measure += ds;
          lip_points.push_back({lip_values->point(q), ds, now != opened});
          if (now != opened)
            {
              closed_measure += ds;
              slip_measure += (now == slipping ? ds : 0.);
              pressure_min = std::min(pressure_min, p[q]);
              pressure_max = std::max(pressure_max, p[q]);
            }
        }
      if (cell_measure > 0)
        {
          state.pressure /= cell_measure;
          state.gap /= cell_measure;
          state.traction /= cell_measure;
          state.closed /= cell_measure;
          state.slipping /= cell_measure;
        }
    }



    template <int dim>
    Tensor<1, dim>
    Penalty<dim>::add_friction(const Tensor<1, dim>              &slip,
                               const std::vector<Tensor<1, dim>> &mean_slip,
                               const std::vector<double>         &mean_gap,
                               const double                       pressure,
                               const double                       kappa,
                               const double                       kappa_t,
                               const double                       length,
                               FullMatrix<double>                &matrix,
                               bool                              &sliding) const
    {
      const unsigned int   n_dofs = matrix.m();
      const double         mu     = this->friction;
      const Tensor<1, dim> trial  = -kappa_t * slip;
      sliding                     = (trial.norm() > mu * pressure);
      if (!sliding)
        {
          // Sticking springs: the force kappa_T s . P_T [[phi_i]].
          for (unsigned int i = 0; i < n_dofs; ++i)
            if (mean_slip[i].norm_square() != 0)
              for (unsigned int j = 0; j < n_dofs; ++j)
                matrix(i, j) +=
                  kappa_t * length * (mean_slip[i] * mean_slip[j]);
          return trial;
        }
      // Slipping: the force F_i = mu p (s/|s|) . P_T [[phi_i]] ds with p =
      // -kappa g; its derivative in u_j: mu kappa [-(s^ . P_T [[phi_i]])
      // (n . [[phi_j]]) + (p / kappa |s|) P_T [[phi_i]] . (I - s^ s^)
      // P_T [[phi_j]]] (the last term vanishes in 2D).
      const double         s      = slip.norm();
      const Tensor<1, dim> along  = slip / s;
      const double         factor = mu * kappa * length;
      for (unsigned int i = 0; i < n_dofs; ++i)
        {
          if (mean_slip[i].norm_square() == 0)
            continue;
          const double along_i = along * mean_slip[i];
          for (unsigned int j = 0; j < n_dofs; ++j)
            matrix(i, j) += factor * (-along_i * mean_gap[j] +
                                      pressure / (kappa * s) *
                                        (mean_slip[i] * mean_slip[j] -
                                         along_i * (along * mean_slip[j])));
        }
      return -mu * pressure * along;
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
      std::map<std::string, double> values{
        {"contact_closed", lips > 0 ? closed / lips : 0.},
        {"contact_pressure_min", closed > 0 ? low : 0.},
        {"contact_pressure_max", high}};
      if (this->friction > 0)
        {
          const double slipped       = Utilities::MPI::sum(slip_measure, comm);
          values["contact_slipping"] = (closed > 0 ? slipped / closed : 0.);
        }
      return values;
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
    typename Interface<dim>::LipState
    Penalty<dim>::lip_state(const CellId &cell) const
    {
      const auto it = cell_states.find(cell);
      return (it == cell_states.end() ? typename Interface<dim>::LipState() :
                                        it->second);
    }



    template <int dim>
    Tensor<1, dim>
    Penalty<dim>::lip_traction(const CellId &cell, const unsigned int q) const
    {
      const auto it = tractions.find(cell);
      if (it == tractions.end() || q >= it->second.size())
        return Tensor<1, dim>();
      return it->second[q];
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Penalty,
                           "penalty",
                           "closed lips press on each other with kappa "
                           "times their interpenetration (subsection "
                           "Penalty).")
  } // namespace Contact
} // namespace xcrack
