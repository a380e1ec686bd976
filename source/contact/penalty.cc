#include <deal.II/base/mpi.h>

#include <xcrack/contact/penalty.h>
#include <xcrack/input_error.h>
#include <xcrack/material.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <sstream>

namespace xcrack
{
  namespace Contact
  {
    template <int dim>
    void
    Penalty<dim>::declare_springs(ParameterHandler  &prm,
                                  const std::string &section,
                                  const std::string &name,
                                  const std::string &default_value)
    {
      std::string lower = name;
      lower[0]          = std::tolower(lower[0]);
      prm.enter_subsection(section);
      prm.declare_entry(
        "Pressure space",
        "cells",
        Patterns::Selection("lip points|cells"),
        "Where the gap is held: at every point of the lips' quadrature "
        "(the pressures oscillate from point to point where many points "
        "hold the few jump unknowns of a cell: the naive space), or its "
        "mean over each cell's lips (one pressure per cell).");
      prm.declare_entry(name + " coefficient",
                        default_value,
                        Patterns::Double(),
                        "kappa = coefficient E / h (h: the cell's size): how "
                        "much stiffer than a cell's worth of material the "
                        "springs between closed lips are (> 0).");
      prm.declare_entry("Tangential " + lower + " coefficient",
                        default_value,
                        Patterns::Double(),
                        "With friction: kappa_T = coefficient E / h, the "
                        "stiffness of the springs that hold sticking lips "
                        "(> 0).");
      prm.leave_subsection();
    }



    template <int dim>
    void
    Penalty<dim>::parse_springs(ParameterHandler  &prm,
                                const std::string &section,
                                const std::string &name)
    {
      std::string lower = name;
      lower[0]          = std::tolower(lower[0]);
      const Plugins::ScopedSubsection scope(prm, section);
      const std::string               normal = name + " coefficient";
      const std::string tangential = "Tangential " + lower + " coefficient";
      coefficient                  = prm.get_double(normal);
      tangential_coefficient       = prm.get_double(tangential);
      per_cell                     = (prm.get("Pressure space") == "cells");
      for (const std::string &entry : {normal, tangential})
        check_input(prm.get_double(entry) > 0,
                    "Contact/" + section + "/" + entry + " = " +
                      prm.get(entry) + ": must be positive.");
    }



    template <int dim>
    void
    Penalty<dim>::declare_parameters(ParameterHandler &prm)
    {
      declare_springs(prm, "Penalty", "Penalty", "1000");
    }



    template <int dim>
    void
    Penalty<dim>::parse_parameters(ParameterHandler &prm)
    {
      parse_springs(prm, "Penalty", "Penalty");
    }



    template <int dim>
    void
    AugmentedLagrangian<dim>::declare_parameters(ParameterHandler &prm)
    {
      Penalty<dim>::declare_springs(prm,
                                    "Augmented Lagrangian",
                                    "Augmentation",
                                    "1000");
    }



    template <int dim>
    void
    AugmentedLagrangian<dim>::parse_parameters(ParameterHandler &prm)
    {
      this->parse_springs(prm, "Augmented Lagrangian", "Augmentation");
      this->augmented = true;
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
          multipliers.clear();
        }
      // Uzawa updates the multipliers once the statuses have settled under
      // the last ones (no status changed in the last assembly, on any
      // rank): updating them at every step lets a group that sits where
      // the pressure space is not stable switch open and closed for ever.
      update_multipliers =
        augmented && !first &&
        Utilities::MPI::sum(n_switched, this->get_mpi_communicator()) == 0;
      n_changed  = 0;
      n_switched = 0;
      lip_points.clear();
      lip_measure    = 0;
      closed_measure = 0;
      slip_measure   = 0;
      pressure_min   = std::numeric_limits<double>::max();
      pressure_max   = 0;
      gap_min        = 0;
    }



    template <int dim>
    void
    Penalty<dim>::assemble(const Assembly::CellInput<dim> &input,
                           FullMatrix<double>             &matrix,
                           Vector<double>                 &rhs,
                           std::string &)
    {
      const unsigned int n_points = lip_values->reinit(input.cell);
      if (n_points == 0)
        return;
      const double h =
        input.cell->diameter() / std::sqrt(static_cast<double>(dim));
      const double kappa =
        coefficient * this->get_material().youngs_modulus / h;
      const double       kappa_t = tangential_coefficient * kappa / coefficient;
      const unsigned int n_dofs  = matrix.m();

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
      // Zero for the penalty; a cell new to the solve starts at zero.
      std::vector<Multipliers>  none(n_groups);
      std::vector<Multipliers> &lambda = (augmented ? multipliers[id] : none);
      lambda.resize(n_groups);
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
              n[q]            = lip_values->crack_normal(q);
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
          // Uzawa: the multipliers take the tractions of this iterate under
          // the last ones (not at a solve's first step, at u = 0).
          if (update_multipliers && input.iterate)
            update(lambda[group], gap, slip, kappa, kappa_t);
          // p = (lambda - kappa g)_+: closed where the lips touch (g <= 0 for
          // the penalty, lambda = 0).
          const bool   closed = (lambda[group].normal - kappa * gap >= 0);
          const double pressure =
            (closed ? lambda[group].normal - kappa * gap : 0.);
          Tensor<1, dim> tangential;
          bool           sliding = false;
          if (closed)
            {
              // The force -p n . [[phi_i]] ds: kappa's springs in the matrix,
              // the multiplier in the right-hand side.
              for (unsigned int i = 0; i < n_dofs; ++i)
                if (mean_gap[i] != 0)
                  {
                    rhs(i) += lambda[group].normal * length * mean_gap[i];
                    for (unsigned int j = 0; j < n_dofs; ++j)
                      matrix(i, j) +=
                        kappa * length * mean_gap[i] * mean_gap[j];
                  }
              if (friction)
                tangential = add_friction(slip,
                                          lambda[group].tangential,
                                          mean_slip,
                                          mean_gap,
                                          pressure,
                                          kappa,
                                          kappa_t,
                                          length,
                                          input.iterate,
                                          matrix,
                                          rhs,
                                          sliding);
            }
          const char now = (!closed ? opened : sliding ? slipping : sticking);
          if (closed)
            gap_min = std::min(gap_min, gap);
          if (known && now != status[group])
            {
              if (n_changed == 0)
                first_changed = lip_values->point(first);
              ++n_changed;
              ++n_switched;
            }
          // Multipliers left for the next assembly are not converged yet.
          else if (augmented && closed && input.iterate && !update_multipliers)
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
                               const Tensor<1, dim>              &multiplier,
                               const std::vector<Tensor<1, dim>> &mean_slip,
                               const std::vector<double>         &mean_gap,
                               const double                       pressure,
                               const double                       kappa,
                               const double                       kappa_t,
                               const double                       length,
                               const Vector<double>              *iterate,
                               FullMatrix<double>                &matrix,
                               Vector<double>                    &rhs,
                               bool                              &sliding) const
    {
      const unsigned int   n_dofs = matrix.m();
      const double         mu     = this->friction;
      const Tensor<1, dim> trial  = multiplier - kappa_t * slip;
      sliding                     = (trial.norm() > mu * pressure);
      if (!sliding)
        {
          // Sticking springs: the force -(lambda_T - kappa_T s) . P_T
          // [[phi_i]] ds.
          for (unsigned int i = 0; i < n_dofs; ++i)
            if (mean_slip[i].norm_square() != 0)
              {
                rhs(i) += length * (multiplier * mean_slip[i]);
                for (unsigned int j = 0; j < n_dofs; ++j)
                  matrix(i, j) +=
                    kappa_t * length * (mean_slip[i] * mean_slip[j]);
              }
          return trial;
        }
      // Slipping: t = mu p d, d = trial / |trial|, p = lambda - kappa g; the
      // force F_i = -t . P_T [[phi_i]] ds has the derivative in u_j
      // mu ds [kappa (n . [[phi_j]]) (d . P_T [[phi_i]]) + (p kappa_T /
      // |trial|) P_T [[phi_i]] . (I - d d) P_T [[phi_j]]] (the last term
      // vanishes in 2D), and the Newton step adds A u_k - F(u_k) to the
      // right-hand side (zero for the penalty: F is then of degree one).
      const double         norm      = trial.norm();
      const Tensor<1, dim> direction = trial / norm;
      const double         curvature = pressure * kappa_t / norm;
      for (unsigned int i = 0; i < n_dofs; ++i)
        {
          if (mean_slip[i].norm_square() == 0)
            continue;
          const double along_i = direction * mean_slip[i];
          double       a_u     = 0;
          for (unsigned int j = 0; j < n_dofs; ++j)
            {
              const double a =
                mu * length *
                (kappa * mean_gap[j] * along_i +
                 curvature * (mean_slip[i] * mean_slip[j] -
                              along_i * (direction * mean_slip[j])));
              matrix(i, j) += a;
              if (iterate)
                a_u += a * (*iterate)[j];
            }
          rhs(i) += a_u + mu * pressure * along_i * length;
        }
      return mu * pressure * direction;
    }



    template <int dim>
    void
    Penalty<dim>::update(Multipliers          &lambda,
                         const double          gap,
                         const Tensor<1, dim> &slip,
                         const double          kappa,
                         const double          kappa_t) const
    {
      lambda.normal        = std::max(lambda.normal - kappa * gap, 0.);
      Tensor<1, dim> trial = lambda.tangential - kappa_t * slip;
      const double   bound = this->friction * lambda.normal;
      if (trial.norm() > bound)
        trial *= bound / trial.norm();
      lambda.tangential = trial;
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
      std::map<std::string, double> values{
        {"contact_closed", lips > 0 ? closed / lips : 0.},
        {"contact_pressure_min", closed > 0 ? low : 0.},
        {"contact_pressure_max", high},
        {"contact_gap_min",
         Utilities::MPI::min(gap_min, this->get_mpi_communicator())}};
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
                           AugmentedLagrangian,
                           "augmented lagrangian",
                           "the penalty's springs plus multipliers updated "
                           "by Uzawa's method at every Newton step: the "
                           "lips do not interpenetrate at convergence "
                           "(subsection Augmented Lagrangian).")

    XCRACK_REGISTER_PLUGIN(Interface,
                           Penalty,
                           "penalty",
                           "closed lips press on each other with kappa "
                           "times their interpenetration (subsection "
                           "Penalty).")
  } // namespace Contact
} // namespace xcrack
