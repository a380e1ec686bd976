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
    unsigned int
    Lagrange<dim>::n_components() const
    {
      return (this->friction > 0 ? dim : 1);
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
      lambda_t.assign(n, {});
      slip.assign(n, {});
      direction.assign(n, {});
      status.assign(n, sticking);
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
          data.jumps.reinit(n_points, n_dofs);
          data.mass.assign(m, 0.);
          data.gaps.assign(n_points, 0.);
          data.stiffness = youngs_modulus *
                           std::sqrt(static_cast<double>(dim)) /
                           cell->diameter();
          for (unsigned int i = 0; i < n_dofs; ++i)
            data.components.push_back(lips.component(i));
          for (unsigned int q = 0; q < n_points; ++q)
            {
              const double ds = lips.normal_ds(q).norm();
              data.normals.push_back(lips.crack_normal(q));
              data.ds.push_back(ds);
              data.points.push_back(lips.point(q));
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  data.jumps(q, i) = lips.jump(i, q);
                  data.gap_rows(q, i) =
                    data.normals[q][data.components[i]] * data.jumps(q, i);
                }
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
      if (this->friction > 0)
        make_frames();
    }



    template <int dim>
    void
    Lagrange<dim>::make_frames()
    {
      // The mean normal of each multiplier's lips, over all ranks.
      const unsigned int  n = space.size();
      std::vector<double> sums(n * dim, 0.);
      for (const auto &[id, data] : cells)
        for (unsigned int q = 0; q < data.points.size(); ++q)
          for (unsigned int j = 0; j < data.multipliers.size(); ++j)
            for (unsigned int d = 0; d < dim; ++d)
              sums[data.multipliers[j] * dim + d] +=
                data.psi[q][j] * data.ds[q] * data.normals[q][d];
      Utilities::MPI::sum(sums, this->get_mpi_communicator(), sums);
      normal.assign(n, Tensor<1, dim>());
      tangents.assign(n, {});
      for (unsigned int k = 0; k < n; ++k)
        {
          for (unsigned int d = 0; d < dim; ++d)
            normal[k][d] = sums[k * dim + d];
          if (normal[k].norm() == 0)
            normal[k][dim - 1] = 1;
          normal[k] /= normal[k].norm();
          if constexpr (dim == 2)
            tangents[k][0] = Tensor<1, dim>({-normal[k][1], normal[k][0]});
          else
            {
              // The axis least aligned with the normal, made orthogonal.
              unsigned int axis = 0;
              for (unsigned int d = 1; d < dim; ++d)
                if (std::abs(normal[k][d]) < std::abs(normal[k][axis]))
                  axis = d;
              Tensor<1, dim> e;
              e[axis]        = 1;
              tangents[k][0] = e - (e * normal[k]) * normal[k];
              tangents[k][0] /= tangents[k][0].norm();
              tangents[k][1] = cross_product_3d(normal[k], tangents[k][0]);
            }
        }
      // The cells' couplings to the slips in those frames.
      for (auto &[id, data] : cells)
        {
          const unsigned int n_dofs = data.coupling.n();
          data.tangential.reinit(data.multipliers.size() * (dim - 1), n_dofs);
          for (unsigned int q = 0; q < data.points.size(); ++q)
            for (unsigned int j = 0; j < data.multipliers.size(); ++j)
              for (unsigned int k = 0; k < dim - 1; ++k)
                {
                  const Tensor<1, dim> &t = tangents[data.multipliers[j]][k];
                  const double          w = data.psi[q][j] * data.ds[q];
                  const double          along_normal = t * data.normals[q];
                  for (unsigned int i = 0; i < n_dofs; ++i)
                    {
                      const unsigned int c = data.components[i];
                      // t . P_T [[phi_i]], [[phi_i]] = jump e_c.
                      data.tangential(j * (dim - 1) + k, i) +=
                        w * data.jumps(q, i) *
                        (t[c] - along_normal * data.normals[q][c]);
                    }
                }
        }
    }



    template <int dim>
    void
    Lagrange<dim>::start_assembly(const bool first)
    {
      n_changed = 0;
      if (first)
        {
          // Closed and sticking everywhere: the first iterate is zero.
          for (unsigned int k = 0; k < status.size(); ++k)
            status[k] = (coupled[k] ? sticking : opened);
          std::fill(lambda.begin(), lambda.end(), 0.);
          std::fill(lambda_t.begin(),
                    lambda_t.end(),
                    std::array<double, dim - 1>());
          return;
        }
      // The weighted gaps and slips of the current iterate, and its gap at
      // each lip point (for the output), over all ranks.
      const bool          friction = (this->friction > 0);
      const unsigned int  n        = space.size();
      std::vector<double> sums(n * (friction ? dim : 1), 0.);
      Vector<double>      u;
      for (auto &[id, data] : cells)
        {
          u.reinit(data.cell->get_fe().n_dofs_per_cell());
          data.cell->get_dof_values(this->get_solution(), u);
          for (unsigned int j = 0; j < data.multipliers.size(); ++j)
            {
              const unsigned int k = data.multipliers[j];
              for (unsigned int i = 0; i < u.size(); ++i)
                sums[friction ? k * dim : k] += data.coupling(j, i) * u[i];
              if (friction)
                for (unsigned int c = 0; c < dim - 1; ++c)
                  for (unsigned int i = 0; i < u.size(); ++i)
                    sums[k * dim + 1 + c] +=
                      data.tangential(j * (dim - 1) + c, i) * u[i];
            }
          for (unsigned int q = 0; q < data.points.size(); ++q)
            {
              data.gaps[q] = 0;
              for (unsigned int i = 0; i < u.size(); ++i)
                data.gaps[q] += data.gap_rows(q, i) * u[i];
            }
        }
      Utilities::MPI::sum(sums, this->get_mpi_communicator(), sums);
      for (unsigned int k = 0; k < n; ++k)
        {
          gap[k] = sums[friction ? k * dim : k];
          if (friction)
            for (unsigned int c = 0; c < dim - 1; ++c)
              slip[k][c] = sums[k * dim + 1 + c];
        }
      update_statuses();
    }



    template <int dim>
    void
    Lagrange<dim>::update_statuses()
    {
      // Every rank alike; the changes are counted by the owner of each
      // multiplier.
      const auto [begin, end] = space.owned_range();
      const double mu         = this->friction;
      for (unsigned int k = 0; k < status.size(); ++k)
        {
          const double c = complementarity * stiffness[k];
          const double normal_trial =
            (coupled[k] ? lambda[k] - c * gap[k] / mass[k] : 0.);
          char                        now = opened;
          std::array<double, dim - 1> d{};
          if (normal_trial > 0)
            {
              now = sticking;
              if (mu > 0)
                {
                  double norm = 0;
                  for (unsigned int i = 0; i < dim - 1; ++i)
                    {
                      d[i] = lambda_t[k][i] - c * slip[k][i] / mass[k];
                      norm += d[i] * d[i];
                    }
                  norm = std::sqrt(norm);
                  if (norm > mu * normal_trial)
                    {
                      now = slipping;
                      for (double &x : d)
                        x /= norm;
                    }
                }
            }
          // A 2D slip that turns round is a change of status; a 3D slip
          // direction settles with the residual.
          const bool changed =
            (now != status[k] ||
             (dim == 2 && now == slipping && d[0] * direction[k][0] < 0));
          if (changed && k >= begin && k < end)
            {
              if (n_changed == 0)
                first_changed = space.location(k);
              ++n_changed;
            }
          status[k]    = now;
          direction[k] = d;
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
      if (it == cells.end())
        return {};
      std::vector<unsigned int> own;
      for (const unsigned int k : it->second.multipliers)
        for (unsigned int c = 0; c < n_components(); ++c)
          own.push_back(k * n_components() + c);
      return own;
    }



    template <int dim>
    void
    Lagrange<dim>::assemble_own(const Assembly::CellInput<dim> &input,
                                const unsigned int              n_dofs,
                                FullMatrix<double>             &matrix,
                                Vector<double> &)
    {
      const CellData    &data = cells.at(input.cell->id());
      const unsigned int nc   = n_components();
      for (unsigned int j = 0; j < data.multipliers.size(); ++j)
        {
          const unsigned int k     = data.multipliers[j];
          const unsigned int row   = n_dofs + j * nc;
          const double       scale = data.mass[j] / data.stiffness;
          if (status[k] == opened)
            {
              // lambda = 0, scaled like the rows of the constraints.
              for (unsigned int c = 0; c < nc; ++c)
                matrix(row + c, row + c) -= scale;
              continue;
            }
          // The gap held at zero, and the pressure's force on the lips.
          for (unsigned int i = 0; i < n_dofs; ++i)
            {
              matrix(row, i) -= data.coupling(j, i);
              matrix(i, row) -= data.coupling(j, i);
            }
          for (unsigned int c = 0; c < nc - 1; ++c)
            {
              // The friction traction's force on the lips, and its row:
              // sticking, the slip held at zero; slipping, lambda_T = mu
              // lambda d.
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  const double b = data.tangential(j * (dim - 1) + c, i);
                  matrix(i, row + 1 + c) -= b;
                  if (status[k] == sticking)
                    matrix(row + 1 + c, i) -= b;
                }
              if (status[k] == slipping)
                {
                  matrix(row + 1 + c, row + 1 + c) += scale;
                  matrix(row + 1 + c, row) -=
                    this->friction * direction[k][c] * scale;
                }
            }
        }
    }



    template <int dim>
    void
    Lagrange<dim>::set_own_values(const std::vector<double> &values)
    {
      const unsigned int nc = n_components();
      AssertDimension(values.size(), lambda.size() * nc);
      for (unsigned int k = 0; k < lambda.size(); ++k)
        {
          lambda[k] = values[k * nc];
          for (unsigned int c = 0; c + 1 < nc; ++c)
            lambda_t[k][c] = values[k * nc + 1 + c];
        }
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
      return space.size() * n_components();
    }



    template <int dim>
    std::pair<unsigned int, unsigned int>
    Lagrange<dim>::owned_own_unknowns() const
    {
      const auto [begin, end] = space.owned_range();
      return {begin * n_components(), end * n_components()};
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
    Lagrange<dim>::friction_traction(const CellData    &data,
                                     const unsigned int q) const
    {
      Tensor<1, dim> t;
      if (this->friction == 0)
        return t;
      for (unsigned int j = 0; j < data.multipliers.size(); ++j)
        for (unsigned int c = 0; c < dim - 1; ++c)
          t += data.psi[q][j] * lambda_t[data.multipliers[j]][c] *
               tangents[data.multipliers[j]][c];
      // Its part in the tangent plane of the point.
      return t - (t * data.normals[q]) * data.normals[q];
    }



    template <int dim>
    Tensor<1, dim>
    Lagrange<dim>::lip_traction(const CellId &cell, const unsigned int q) const
    {
      const auto it = cells.find(cell);
      if (it == cells.end() || q >= it->second.points.size())
        return Tensor<1, dim>();
      return pressure(it->second, q) * it->second.normals[q] +
             friction_traction(it->second, q);
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
          state.traction +=
            (p * data.normals[q] + friction_traction(data, q)) * data.ds[q];
          state.closed += (p > 0 ? data.ds[q] : 0.);
          for (unsigned int j = 0; j < data.multipliers.size(); ++j)
            if (status[data.multipliers[j]] == slipping)
              state.slipping += data.psi[q][j] * data.ds[q];
        }
      if (length > 0)
        {
          state.pressure /= length;
          state.gap /= length;
          state.traction /= length;
          state.closed /= length;
          state.slipping /= length;
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
      double lips = 0, closed = 0, slipped = 0;
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
                for (unsigned int j = 0; j < data.multipliers.size(); ++j)
                  if (status[data.multipliers[j]] == slipping)
                    slipped += data.psi[q][j] * data.ds[q];
              }
          }
      // The gap held where closed: the weighted gap of each closed
      // multiplier over its mass (zero to round-off at convergence).
      double gap_min = 0;
      for (unsigned int k = 0; k < lambda.size(); ++k)
        if (status[k] != opened && mass[k] > 0)
          gap_min = std::min(gap_min, gap[k] / mass[k]);
      const MPI_Comm comm = this->get_mpi_communicator();
      lips                = Utilities::MPI::sum(lips, comm);
      closed              = Utilities::MPI::sum(closed, comm);
      slipped             = Utilities::MPI::sum(slipped, comm);
      low                 = Utilities::MPI::min(low, comm);
      high                = Utilities::MPI::max(high, comm);
      std::map<std::string, double> values{
        {"contact_closed", lips > 0 ? closed / lips : 0.},
        {"contact_pressure_min", closed > 0 ? low : 0.},
        {"contact_pressure_max", high},
        {"contact_gap_min", gap_min},
        {"contact_multipliers", static_cast<double>(lambda.size())}};
      if (this->friction > 0)
        values["contact_slipping"] = (closed > 0 ? slipped / closed : 0.);
      return values;
    }

    XCRACK_REGISTER_PLUGIN(Interface,
                           Lagrange,
                           "lagrange",
                           "the contact tractions as Lagrange multipliers on "
                           "a stable space of the lips, which hold the lips "
                           "exactly (subsection Lagrange; saddle-point "
                           "systems: Linear solver/Type = direct).")
  } // namespace Contact
} // namespace xcrack
