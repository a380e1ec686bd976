#include <xcrack/assembly/loads.h>

#include <cmath>
#include <sstream>

namespace xcrack
{
  namespace Assembly
  {
    namespace
    {
      /// Describe the first value of @p values that is not finite, at the
      /// point of @p points where it is, into @p culprit (if still empty).
      template <int dim>
      void
      check_finite(const std::vector<Vector<double>> &values,
                   const std::vector<Point<dim>>     &points,
                   const std::string                 &entry,
                   std::string                       &culprit)
      {
        for (unsigned int q = 0; q < values.size() && culprit.empty(); ++q)
          for (const double v : values[q])
            if (!std::isfinite(v))
              {
                std::ostringstream message;
                message << entry << " is not finite at (" << points[q]
                        << "), where it is used: " << v << ".";
                culprit = message.str();
                break;
              }
      }



      /// Add @p factor times int load . phi_i, integrated by @p values (on
      /// a cell or a face), to @p rhs.
      template <int dim>
      void
      add_load(const FEValuesBase<dim>           &values,
               const std::vector<Vector<double>> &load,
               const double                       factor,
               Vector<double>                    &rhs)
      {
        const FiniteElement<dim> &fe = values.get_fe();
        for (const unsigned int q : values.quadrature_point_indices())
          for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
            {
              const unsigned int c = fe.system_to_component_index(i).first;
              rhs(i) +=
                factor * values.shape_value(i, q) * load[q](c) * values.JxW(q);
            }
      }
    } // namespace



    template <int dim>
    BoundaryTractions<dim>::BoundaryTractions(
      const hp::FECollection<dim>    &fe_collection,
      const hp::QCollection<dim - 1> &face_quadrature)
      : face_values(fe_collection,
                    face_quadrature,
                    update_values | update_quadrature_points |
                      update_JxW_values)
    {}



    template <int dim>
    void
    BoundaryTractions<dim>::assemble(const CellInput<dim> &input,
                                     FullMatrix<double> &,
                                     Vector<double> &rhs,
                                     std::string    &culprit)
    {
      const auto &neumann = input.state->loads->neumann;
      if (neumann.empty() || !input.cell->at_boundary())
        return;
      for (const auto &face : input.cell->face_iterators())
        if (face->at_boundary())
          {
            const auto it = neumann.find(face->boundary_id());
            if (it == neumann.end())
              continue;
            face_values.reinit(input.cell, face);
            const FEFaceValues<dim> &values =
              face_values.get_present_fe_values();
            load.resize(values.n_quadrature_points, Vector<double>(dim));
            it->second->vector_value_list(values.get_quadrature_points(), load);
            check_finite(load,
                         values.get_quadrature_points(),
                         input.state->loads->section + "/Neumann (boundary " +
                           std::to_string(face->boundary_id()) + ")",
                         culprit);
            add_load(values, load, input.state->factor, rhs);
          }
    }



    template <int dim>
    UpdateFlags
    BodyForce<dim>::update_flags() const
    {
      return update_values | update_quadrature_points | update_JxW_values;
    }



    template <int dim>
    void
    BodyForce<dim>::assemble(const CellInput<dim> &input,
                             FullMatrix<double> &,
                             Vector<double> &rhs,
                             std::string    &culprit)
    {
      const Function<dim> *force = input.state->loads->body_force.get();
      if (!force)
        return;
      const FEValues<dim> &values = *input.fe_values;
      load.resize(values.n_quadrature_points, Vector<double>(dim));
      force->vector_value_list(values.get_quadrature_points(), load);
      check_finite(load,
                   values.get_quadrature_points(),
                   input.state->loads->section + "/Body force",
                   culprit);
      add_load(values, load, input.state->factor, rhs);
    }



    template <int dim>
    LipPressure<dim>::LipPressure(const Enrichment<dim> &enrichment)
      : lip_values(enrichment)
    {}



    template <int dim>
    void
    LipPressure<dim>::assemble(const CellInput<dim> &input,
                               FullMatrix<double> &,
                               Vector<double> &rhs,
                               std::string    &culprit)
    {
      const Function<dim> *pressure = input.state->loads->lip_pressure.get();
      if (!pressure || lip_values.reinit(input.cell) == 0)
        return;
      const double factor = input.state->factor;
      bool         finite = true;
      for (unsigned int q = 0; q < lip_values.n_points(); ++q)
        {
          const double p             = pressure->value(lip_values.point(q));
          finite                     = finite && std::isfinite(p);
          const Tensor<1, dim> &n_ds = lip_values.normal_ds(q);
          for (unsigned int i = 0; i < rhs.size(); ++i)
            rhs(i) += factor * p * n_ds[lip_values.component(i)] *
                      lip_values.jump(i, q);
        }
      if (!finite && culprit.empty())
        {
          std::ostringstream message;
          message << input.state->loads->section
                  << "/Lip pressure is not finite on the lips in the cell at ("
                  << input.cell->center() << ").";
          culprit = message.str();
        }
    }



    template class BoundaryTractions<2>;
    template class BoundaryTractions<3>;
    template class BodyForce<2>;
    template class BodyForce<3>;
    template class LipPressure<2>;
    template class LipPressure<3>;
  } // namespace Assembly
} // namespace xcrack
