#ifndef xcrack_elasticity_templates_h
#define xcrack_elasticity_templates_h

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/grid/grid_tools.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <xcrack/condition_number.h>
#include <xcrack/elasticity.h>
#include <xcrack/exact_solution.h>
#include <xcrack/fracture/displacement_jump.h>
#include <xcrack/fracture/interaction_integral.h>
#include <xcrack/input_error.h>
#include <xcrack/output.h>
#include <xcrack/xfem/cell_quadrature.h>
#include <xcrack/xfem/enriched_dirichlet.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>

namespace xcrack
{
  template <int dim>
  void
  ElasticityProblem<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Discretization");
    {
      prm.declare_entry("Degree",
                        "1",
                        Patterns::Integer(1, 2),
                        "Polynomial degree of the displacement (Q1 or Q2).");
    }
    prm.leave_subsection();

    EnrichmentParameters::declare_parameters(prm);
    FractureParameters::declare_parameters(prm);
  }



  template <int dim>
  ElasticityProblem<dim>::ElasticityProblem(ParameterHandler &prm,
                                            const MPI_Comm    mpi_communicator)
    : mpi_communicator(mpi_communicator)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , prm(prm)
    // Only the 2:1 balance, which p4est enforces globally: the other
    // smoothing flags act on each rank's part of the mesh (with them, a
    // cell near a partition boundary was refined on one rank and not on
    // two, and K differed in the sixth digit: two collinear cracks, fifth
    // mesh).
    , triangulation(mpi_communicator,
                    Triangulation<dim>::limit_level_difference_at_vertices)
    , level_sets(triangulation)
  {
    run_parameters.parse_parameters(prm);
    check_input(run_parameters.dimension == dim,
                "Dimension = " + std::to_string(run_parameters.dimension) +
                  " but this is a " + std::to_string(dim) + "D problem.");
    material.parse_parameters(prm);
    mesh_description.parse_parameters(prm);
    linear_solver.parse_parameters(prm);

    FunctionConstants constants = material.constants(dim);
    constants["pi"]             = numbers::PI;
    for (const auto &[name, value] : run_parameters.user_constants)
      {
        check_input(constants.count(name) == 0,
                    "Function constants: '" + name +
                      "' is a reserved name (E, nu, mu, lambda, pi).");
        constants[name] = value;
      }
    exact_solution = ExactSolution::create<dim>(prm, constants, material);
    boundary_conditions.parse_parameters(prm, constants, exact_solution);
    refinement.parse_parameters(prm, constants);
    cracks.parse_parameters(prm);
    fracture_parameters.parse_parameters(prm, constants);
    check_input(dim == 2 ? !fracture_parameters.reference_3d :
                           !fracture_parameters.reference_2d,
                "Fracture parameters/Reference K: give " +
                  std::string(dim == 2 ? "'K_I; K_II'" : "'K_I; K_II; K_III'") +
                  " in " + std::to_string(dim) + "D.");

    prm.enter_subsection("Discretization");
    degree = prm.get_integer("Degree");
    prm.leave_subsection();


    mesh_description.create(triangulation);
    boundary_conditions.check_against(triangulation);
    cracks.check_against(triangulation);
    check_input(!boundary_conditions.dirichlet.empty() ||
                  !boundary_conditions.pinned.empty(),
                "Boundary conditions/Dirichlet and Pinned points are empty: "
                "without any prescribed displacement the rigid body motions "
                "are free and the problem has no unique solution.");

    check_input(!boundary_conditions.lip_pressure || cracks.size() > 0,
                "Boundary conditions/Lip pressure is set but there is no "
                "crack (Cracks/Number of cracks = 0).");
    if (cracks.size() > 0)
      {
        EnrichmentParameters enrichment_parameters;
        enrichment_parameters.parse_parameters(prm);
        std::vector<const CrackGeometry<dim> *> crack_list;
        for (unsigned int c = 0; c < cracks.size(); ++c)
          crack_list.push_back(&cracks[c]);
        enrichment = std::make_unique<Enrichment<dim>>(crack_list,
                                                       degree,
                                                       enrichment_parameters);
        // Several cracks: classify the coarse mesh once now, so that
        // cracks whose enriched zones meet stop the run here, before any
        // result is written.
        if (cracks.size() > 1)
          {
            DoFHandler<dim> probe(triangulation);
            enrichment->set_fe_indices(probe);
          }
        // Gauss rules per element: the cells of the tip zone carry the
        // non-polynomial branch functions and get two more points.
        for (const auto &fe : enrichment->get_fe_collection())
          {
            fe_collection.push_back(fe);
            quadrature_collection.push_back(QGauss<dim>(
              degree +
              (fe_collection.size() - 1 >= Enrichment<dim>::tip ? 3 : 1)));
          }
      }
    else
      {
        fe_collection.push_back(FESystem<dim>(FE_Q<dim>(degree), dim));
        quadrature_collection.push_back(QGauss<dim>(degree + 1));
      }
    face_quadrature_collection.push_back(QGauss<dim - 1>(degree + 1));

    // The output directory must be usable: this is the last check before
    // any result is written.
    const std::filesystem::path dir(run_parameters.output_directory);
    check_input(!std::filesystem::exists(dir) ||
                  std::filesystem::is_directory(dir),
                "Output directory = " + run_parameters.output_directory +
                  ": exists and is not a directory.");
  }



  template <int dim>
  const Statistics &
  ElasticityProblem<dim>::get_statistics() const
  {
    return statistics;
  }



  template <int dim>
  void
  ElasticityProblem<dim>::setup_system()
  {
    {
      TimerOutput::Scope t(*timer, "setup");
      dof_handler.reinit(triangulation);
      if (enrichment)
        enrichment->set_fe_indices(dof_handler);
    }
    // The level-set fields follow the enrichment's fit-to-vertex shifts;
    // gathering ties the branch DoFs along the fronts they give.
    update_level_sets();
    std::vector<std::vector<std::vector<FrontPoint<dim>>>> fronts;
    if (enrichment && enrichment->get_parameters().gather)
      for (unsigned int c = 0; c < cracks.size(); ++c)
        {
          CrackSurface<dim> surface;
          surface.extract(level_sets, c);
          fronts.push_back(surface.fronts());
        }

    TimerOutput::Scope t(*timer, "setup");
    dof_handler.distribute_dofs(fe_collection);
    enriched_dofs      = (enrichment ? enrichment->enriched_dofs(dof_handler) :
                                       IndexSet(dof_handler.n_dofs()));
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    if (enrichment)
      enrichment->make_constraints(dof_handler, constraints, fronts);

    make_dirichlet_constraints();
    constraints.close();

    // Gathered DoFs are tied to masters that may be owned by another rank
    // and lie outside the relevant set: assembly writes to their rows too.
    IndexSet rows = locally_relevant_dofs;
    if (enrichment)
      rows.add_indices(enrichment->gathering_masters());
    DynamicSparsityPattern dsp(rows);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned_dofs,
                                               mpi_communicator,
                                               rows);
    system_matrix.reinit(locally_owned_dofs,
                         locally_owned_dofs,
                         dsp,
                         mpi_communicator);
    system_rhs.reinit(locally_owned_dofs, mpi_communicator);
    solution.reinit(locally_owned_dofs,
                    locally_relevant_dofs,
                    mpi_communicator);
  }



  template <int dim>
  void
  ElasticityProblem<dim>::update_level_sets()
  {
    if (cracks.size() == 0)
      return;
    TimerOutput::Scope t(*timer, "levelset");
    level_sets.update(cracks,
                      enrichment ? enrichment->lsn_shift() :
                                   std::vector<std::vector<double>>());
  }



  template <int dim>
  void
  ElasticityProblem<dim>::report_crack_surface()
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
        pcout << line.str() << std::endl;
      }
    statistics.add_value("crack_measure", measure);
    statistics.add_value("front_length", front_length);
    statistics.add_value("max_opening", largest_opening);
  }



  template <int dim>
  void
  ElasticityProblem<dim>::make_dirichlet_constraints()
  {
    // Pinned vertices: their standard DoFs of the listed components. A pin
    // where the vertex carries enrichment would not hold the displacement
    // there (the enriched functions add to it): refused.
    for (const auto &[point, mask] : boundary_conditions.pinned)
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          for (const unsigned int v : cell->vertex_indices())
            if (cell->vertex(v).distance(point) < 1e-10 * cell->diameter())
              {
                const FiniteElement<dim>            &fe = cell->get_fe();
                std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
                cell->get_dof_indices(dofs);
                for (unsigned int k = 0; k < fe.n_dofs_per_vertex(); ++k)
                  {
                    const unsigned int i = v * fe.n_dofs_per_vertex() + k;
                    const unsigned int c =
                      fe.system_to_component_index(i).first;
                    if (!mask[c])
                      continue;
                    if (enrichment && Enrichment<dim>::is_enriched_dof(fe, i))
                      {
                        std::ostringstream where;
                        where << point;
                        check_input(constraints.is_constrained(dofs[i]),
                                    "Boundary conditions/Pinned points: (" +
                                      where.str() +
                                      ") lies where the crack enriches the "
                                      "space; pin a vertex farther from it.");
                        continue;
                      }
                    if (!constraints.is_constrained(dofs[i]))
                      {
                        constraints.add_line(dofs[i]);
                        constraints.set_inhomogeneity(dofs[i], 0.);
                      }
                  }
              }

    if (enrichment)
      {
        make_enriched_dirichlet_constraints(dof_handler,
                                            *enrichment,
                                            boundary_conditions,
                                            constraints);
        return;
      }
    for (const auto &[id, function] : boundary_conditions.dirichlet)
      VectorTools::interpolate_boundary_values(
        dof_handler,
        id,
        *function,
        constraints,
        boundary_conditions.dirichlet_mask.at(id));
  }



  template <int dim>
  const FEValues<dim> &
  ElasticityProblem<dim>::reinit_fe_values(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    hp::FEValues<dim>                                    &hp_fe_values,
    std::unique_ptr<FEValues<dim>>                       &special_values,
    const unsigned int                                    n_points_1d) const
  {
    if (const Quadrature<dim> *rule =
          (enrichment ? enrichment->special_quadrature(cell, n_points_1d) :
                        nullptr))
      {
        special_values =
          std::make_unique<FEValues<dim>>(cell->get_fe(),
                                          *rule,
                                          hp_fe_values.get_update_flags());
        special_values->reinit(cell);
        return *special_values;
      }
    hp_fe_values.reinit(cell);
    return hp_fe_values.get_present_fe_values();
  }



  template <int dim>
  void
  ElasticityProblem<dim>::assemble_system()
  {
    TimerOutput::Scope t(*timer, "assemble");

    const double lambda = material.lambda(dim);
    const double mu     = material.mu();

    hp::FEValues<dim>                hp_fe_values(fe_collection,
                                   quadrature_collection,
                                   update_values | update_gradients |
                                     update_quadrature_points |
                                     update_JxW_values);
    hp::FEFaceValues<dim>            hp_fe_face_values(fe_collection,
                                            face_quadrature_collection,
                                            update_values |
                                              update_quadrature_points |
                                              update_JxW_values);
    const FEValuesExtractors::Vector displacement(0);

    FullMatrix<double>                   cell_matrix;
    Vector<double>                       cell_rhs;
    std::vector<types::global_dof_index> local_dof_indices;
    std::vector<SymmetricTensor<2, dim>> eps;
    std::vector<double>                  div;
    std::vector<Vector<double>>          load;
    std::unique_ptr<FEValues<dim>>       special_values;

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const FEValues<dim> &fe_values =
            reinit_fe_values(cell, hp_fe_values, special_values, degree + 1);
          const unsigned int n_dofs = fe_values.dofs_per_cell;
          cell_matrix.reinit(n_dofs, n_dofs);
          cell_rhs.reinit(n_dofs);
          eps.resize(n_dofs);
          div.resize(n_dofs);

          if (boundary_conditions.body_force)
            {
              load.resize(fe_values.n_quadrature_points, Vector<double>(dim));
              boundary_conditions.body_force->vector_value_list(
                fe_values.get_quadrature_points(), load);
            }

          for (const unsigned int q : fe_values.quadrature_point_indices())
            {
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  eps[i] = fe_values[displacement].symmetric_gradient(i, q);
                  div[i] = trace(eps[i]);
                }
              const double JxW = fe_values.JxW(q);
              for (unsigned int i = 0; i < n_dofs; ++i)
                {
                  for (unsigned int j = 0; j <= i; ++j)
                    cell_matrix(i, j) +=
                      (lambda * div[i] * div[j] + 2. * mu * (eps[i] * eps[j])) *
                      JxW;
                  if (boundary_conditions.body_force)
                    {
                      const unsigned int c =
                        fe_values.get_fe().system_to_component_index(i).first;
                      cell_rhs(i) +=
                        fe_values.shape_value(i, q) * load[q](c) * JxW;
                    }
                }
            }
          for (unsigned int i = 0; i < n_dofs; ++i)
            for (unsigned int j = i + 1; j < n_dofs; ++j)
              cell_matrix(i, j) = cell_matrix(j, i);

          for (const auto &face : cell->face_iterators())
            if (face->at_boundary())
              {
                const auto it =
                  boundary_conditions.neumann.find(face->boundary_id());
                if (it == boundary_conditions.neumann.end())
                  continue;
                hp_fe_face_values.reinit(cell, face);
                const FEFaceValues<dim> &fe_face_values =
                  hp_fe_face_values.get_present_fe_values();
                load.resize(fe_face_values.n_quadrature_points,
                            Vector<double>(dim));
                it->second->vector_value_list(
                  fe_face_values.get_quadrature_points(), load);
                for (const unsigned int q :
                     fe_face_values.quadrature_point_indices())
                  for (unsigned int i = 0; i < n_dofs; ++i)
                    {
                      const unsigned int c =
                        fe_values.get_fe().system_to_component_index(i).first;
                      cell_rhs(i) += fe_face_values.shape_value(i, q) *
                                     load[q](c) * fe_face_values.JxW(q);
                    }
              }

          if (boundary_conditions.lip_pressure)
            add_lip_pressure(cell, cell_rhs);

          local_dof_indices.resize(n_dofs);
          cell->get_dof_indices(local_dof_indices);
          constraints.distribute_local_to_global(cell_matrix,
                                                 cell_rhs,
                                                 local_dof_indices,
                                                 system_matrix,
                                                 system_rhs);
        }

    system_matrix.compress(VectorOperation::add);
    system_rhs.compress(VectorOperation::add);
  }



  template <int dim>
  NonMatching::ImmersedSurfaceQuadrature<dim>
  ElasticityProblem<dim>::lip_rule(
    const typename DoFHandler<dim>::active_cell_iterator &cell) const
  {
    if (!enrichment ||
        !(enrichment->is_split(cell) || enrichment->is_tip(cell)))
      return {};
    std::vector<double> lsn, lst;
    for (const unsigned int v : cell->vertex_indices())
      {
        lsn.push_back(enrichment->crack_of(cell).lsn(cell->vertex(v)));
        lst.push_back(enrichment->crack_of(cell).lst(cell->vertex(v)));
      }
    // Where the front crosses a 3D cell, four boxes per direction
    // (CellQuadrature::lip_rule; 2D tip cells are split exactly).
    // On the lips of a tip cell the jumps of the branch functions grow like
    // sqrt(r) from the front: Gauss rules need more points there (2 points
    // on sqrt(x) over [0, 1] err by 1 %, 6 points by 5e-4).
    const unsigned int n_points =
      (enrichment->is_tip(cell) ?
         std::max(degree + 1,
                  enrichment->get_parameters().tip_quadrature_points) :
         degree + 1);
    return CellQuadrature::lip_rule<dim>(lsn, lst, n_points, 4);
  }



  template <int dim>
  void
  ElasticityProblem<dim>::add_lip_pressure(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    Vector<double>                                       &cell_rhs) const
  {
    const auto rule = lip_rule(cell);
    if (rule.size() == 0)
      return;
    const FiniteElement<dim> &fe = cell->get_fe();
    FEValues<dim>             sides(
      fe,
      Quadrature<dim>(CellQuadrature::both_sides(rule.get_points(),
                                                 rule.get_normal_vectors())),
      update_values | update_quadrature_points | update_jacobians);
    sides.reinit(cell);
    for (unsigned int q = 0; q < rule.size(); ++q)
      {
        const Tensor<1, dim> n_ds =
          CellQuadrature::mapped_normal<dim>(sides.jacobian(2 * q),
                                             rule.normal_vector(q),
                                             rule.weight(q));
        const double p = boundary_conditions.lip_pressure->value(
          sides.quadrature_point(2 * q));
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            const unsigned int c = fe.system_to_component_index(i).first;
            cell_rhs(i) +=
              p * n_ds[c] *
              (sides.shape_value(i, 2 * q) - sides.shape_value(i, 2 * q + 1));
          }
      }
  }



  template <int dim>
  unsigned int
  ElasticityProblem<dim>::solve()
  {
    TimerOutput::Scope t(*timer, "solve");

    std::vector<std::vector<bool>> constant_modes;
    if (linear_solver.type != "direct")
      DoFTools::extract_constant_modes(dof_handler,
                                       ComponentMask(dim, true),
                                       constant_modes);

    TrilinosWrappers::MPI::Vector distributed(locally_owned_dofs,
                                              mpi_communicator);
    const unsigned int iterations = linear_solver.solve(system_matrix,
                                                        distributed,
                                                        system_rhs,
                                                        constant_modes);
    constraints.distribute(distributed);
    solution = distributed;
    return iterations;
  }



  template <int dim>
  std::pair<double, double>
  ElasticityProblem<dim>::compute_errors() const
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
    std::unique_ptr<FEValues<dim>>           special_values;

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
  ElasticityProblem<dim>::compute_max_displacement() const
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
  types::global_dof_index
  ElasticityProblem<dim>::n_free_enriched_dofs() const
  {
    types::global_dof_index n = 0;
    for (const auto dof : enriched_dofs)
      if (locally_owned_dofs.is_element(dof) &&
          !constraints.is_constrained(dof))
        ++n;
    return Utilities::MPI::sum(n, mpi_communicator);
  }



  template <int dim>
  void
  ElasticityProblem<dim>::output_results(const unsigned int cycle)
  {
    TimerOutput::Scope t(*timer, "output");

    const StressPostprocessor<dim> stress(material);
    DataOut<dim>                   data_out;
    data_out.attach_dof_handler(dof_handler);
    data_out.add_data_vector(
      solution,
      std::vector<std::string>(dim, "displacement"),
      DataOut<dim>::type_dof_data,
      std::vector<DataComponentInterpretation::DataComponentInterpretation>(
        dim, DataComponentInterpretation::component_is_part_of_vector));
    data_out.add_data_vector(solution, stress);
    Vector<float> subdomain(triangulation.n_active_cells());
    subdomain = triangulation.locally_owned_subdomain();
    data_out.add_data_vector(subdomain, "subdomain");
    // Which functions each cell carries (0 plain, 1 jump, 2 branch, 3 both)
    // and what the crack does to it (0 nothing, 1 splits it, 2 front in it,
    // 3 front within a diameter): what a user checks first when an enriched
    // run looks wrong.
    Vector<float> enrichment_index(triangulation.n_active_cells());
    Vector<float> crack_category(triangulation.n_active_cells());
    if (enrichment)
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            enrichment_index[cell->active_cell_index()] =
              cell->active_fe_index();
            crack_category[cell->active_cell_index()] =
              enrichment->cell_category(cell);
          }
    if (enrichment)
      {
        data_out.add_data_vector(enrichment_index, "enrichment");
        data_out.add_data_vector(crack_category, "crack_cell");
      }
    for (unsigned int i = 0; i < cracks.size(); ++i)
      {
        const std::string suffix =
          (cracks.size() > 1 ? std::to_string(i + 1) : "");
        data_out.add_data_vector(level_sets.get_dof_handler(),
                                 level_sets.lsn(i),
                                 "lsn" + suffix);
        data_out.add_data_vector(level_sets.get_dof_handler(),
                                 level_sets.lst(i),
                                 "lst" + suffix);
      }
    data_out.build_patches(degree);
    // crack-<cycle>.vtu for one crack, crack<i>-<cycle>.vtu for several.
    if (enrichment)
      for (unsigned int c = 0; c < crack_surfaces.size(); ++c)
        crack_surfaces[c].write_vtu(
          run_parameters.output_directory + "/crack" +
            (cracks.size() > 1 ? std::to_string(c + 1) : "") + "-" +
            Utilities::int_to_string(cycle, 3) + ".vtu",
          dof_handler,
          solution);

    const std::string  dir  = run_parameters.output_directory + "/";
    const std::string  base = "solution-" + Utilities::int_to_string(cycle, 3);
    const unsigned int rank =
      Utilities::MPI::this_mpi_process(mpi_communicator);
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    {
      std::ofstream out(dir + base + "." + Utilities::int_to_string(rank, 4) +
                        ".vtu");
      data_out.write_vtu(out);
    }
    if (rank == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int r = 0; r < n_ranks; ++r)
          pieces.push_back(base + "." + Utilities::int_to_string(r, 4) +
                           ".vtu");
        std::ofstream pvtu(dir + base + ".pvtu");
        data_out.write_pvtu_record(pvtu, pieces);
        pvd_records.emplace_back(cycle, base + ".pvtu");
        std::ofstream pvd(dir + "solution.pvd");
        DataOutBase::write_pvd_record(pvd, pvd_records);
      }
  }



  template <int dim>
  void
  ElasticityProblem<dim>::print_convergence_table() const
  {
    pcout << std::endl
          << "Convergence (rates against the mean cell size h = cells^(-1/"
          << dim << "))" << std::endl
          << "cycle     cells      dofs   L2_error  rate  energy_error  rate"
          << std::endl;
    for (unsigned int r = 0; r < statistics.n_rows(); ++r)
      {
        const auto value = [&](const char *c) { return statistics.get(c, r); };
        pcout << std::setw(5) << r << std::setw(10)
              << static_cast<long long>(value("cells")) << std::setw(10)
              << static_cast<long long>(value("dofs")) << std::scientific
              << std::setprecision(3) << std::setw(11) << value("L2_error");
        const auto rate = [&](const char *c) {
          if (r == 0)
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



  template <int dim>
  void
  ElasticityProblem<dim>::compute_fracture_parameters(const unsigned int cycle)
  {
    TimerOutput::Scope t(*timer, "fracture");
    // The fronts of all cracks, numbered one after the other.
    std::vector<std::vector<FrontPoint<dim>>> fronts;
    for (const auto &surface : crack_surfaces)
      fronts.insert(fronts.end(),
                    surface.fronts().begin(),
                    surface.fronts().end());
    if (fronts.empty())
      return;

    hp::FEValues<dim>              hp_fe_values(fe_collection,
                                   quadrature_collection,
                                   update_values | update_gradients |
                                     update_quadrature_points |
                                     update_JxW_values |
                                     update_inverse_jacobians);
    std::unique_ptr<FEValues<dim>> special_values;
    const auto fe_values_of = [&](const auto &cell) -> const FEValues<dim> & {
      return reinit_fe_values(cell, hp_fe_values, special_values, degree + 1);
    };
    const auto lips_of = [&](const auto                  &cell,
                             std::vector<Point<dim>>     &points,
                             std::vector<double>         &weights,
                             std::vector<Tensor<1, dim>> &normals) {
      const auto rule = lip_rule(cell);
      points          = rule.get_points();
      weights         = rule.get_weights();
      normals         = rule.get_normal_vectors();
    };
    const InteractionIntegral<dim> integral(fracture_parameters, material);
    const auto                     values = integral.compute(dof_handler,
                                         solution,
                                         fronts,
                                         fe_values_of,
                                         boundary_conditions.lip_pressure.get(),
                                         lips_of,
                                         boundary_conditions.body_force.get());

    // The cross-check by the displacement jumps over the crown.
    std::vector<std::array<double, 3>> jump_k;
    for (const auto &v : values)
      jump_k.push_back(displacement_jump_k(
        dof_handler, solution, v.point, material, v.r_inf, v.r_sup));

    // The reference K at each point, if given.
    std::vector<Vector<double>> reference(values.size());
    const Function<dim>        *reference_function = nullptr;
    if constexpr (dim == 2)
      reference_function = fracture_parameters.reference_2d.get();
    else
      reference_function = fracture_parameters.reference_3d.get();
    if (reference_function)
      for (unsigned int i = 0; i < values.size(); ++i)
        {
          reference[i].reinit(dim);
          reference_function->vector_value(values[i].point.position,
                                           reference[i]);
        }
    const auto k_of = [](const FrontValues<dim> &v, const unsigned int m) {
      return (m == 0 ? v.k_I : m == 1 ? v.k_II : v.k_III);
    };
    constexpr unsigned int n_modes       = dim;
    const char            *mode_names[3] = {"K_I", "K_II", "K_III"};

    const auto warn_crown = [&](const FrontValues<dim> &v) {
      if (!v.crown_clear)
        pcout << "  Warning: the crown of " << (dim == 2 ? "tip " : "front ")
              << v.front + 1 << " (r_sup = " << v.r_sup
              << ") reaches the boundary or another "
              << (dim == 2 ? "tip" : "front")
              << "; its K and G are unreliable. Use smaller Fracture "
                 "parameters/Crown radii or a finer mesh there."
              << std::endl;
    };

    // On screen, K's are rounded to 1e-6 of the largest one: a K that
    // vanishes by symmetry then reads 0 rather than round-off that differs
    // between builds (the CSV files and the statistics keep every digit).
    if constexpr (dim == 2)
      for (unsigned int i = 0; i < values.size(); ++i)
        {
          const auto  &v = values[i];
          const double quantum =
            1e-6 * std::max({std::abs(v.k_I), std::abs(v.k_II), 1e-300});
          const auto rounded = [&](const double k) {
            return std::round(k / quantum) * quantum + 0.;
          };
          pcout << "  tip " << i + 1 << std::scientific << std::setprecision(6)
                << ": K_I = " << rounded(v.k_I)
                << ", K_II = " << rounded(v.k_II) << ", G = " << v.g
                << ", G_Irwin = " << v.g_irwin << std::endl
                << "    displacement jumps: K_I = " << rounded(jump_k[i][0])
                << ", K_II = " << rounded(jump_k[i][1]) << std::defaultfloat
                << std::endl;
          warn_crown(v);
          const std::string suffix = "_" + std::to_string(i + 1);
          statistics.add_value("K_I" + suffix, v.k_I);
          statistics.add_value("K_II" + suffix, v.k_II);
          statistics.add_value("G" + suffix, v.g);
          statistics.add_value("K_I_jump" + suffix, jump_k[i][0]);
          statistics.add_value("K_II_jump" + suffix, jump_k[i][1]);
        }
    else
      // Per front: the range and mean of each K over its nodes, and the
      // largest gap between G-theta and Irwin's G.
      for (unsigned int f = 0; f < fronts.size(); ++f)
        {
          double       k_min[3] = {1e300, 1e300, 1e300};
          double       k_max[3] = {-1e300, -1e300, -1e300}, k_mean[3] = {};
          double       largest = 1e-300, irwin_gap = 0, g_max = 1e-300;
          unsigned int n = 0;
          for (const auto &v : values)
            if (v.front == f)
              {
                for (unsigned int m = 0; m < 3; ++m)
                  {
                    k_min[m] = std::min(k_min[m], k_of(v, m));
                    k_max[m] = std::max(k_max[m], k_of(v, m));
                    k_mean[m] += k_of(v, m);
                    largest = std::max(largest, std::abs(k_of(v, m)));
                  }
                irwin_gap = std::max(irwin_gap, std::abs(v.g - v.g_irwin));
                g_max     = std::max(g_max, std::abs(v.g));
                ++n;
              }
          const double quantum = 1e-6 * largest;
          const auto   rounded = [&](const double k) {
            return std::round(k / quantum) * quantum + 0.;
          };
          std::string basis;
          for (const auto &v : values)
            if (v.front == f)
              basis = v.basis;
          pcout << "  front " << f + 1 << ": " << n << " points (" << basis
                << "), " << std::scientific << std::setprecision(6);
          for (unsigned int m = 0; m < 3; ++m)
            {
              k_mean[m] /= n;
              pcout << (m > 0 ? "; " : "") << mode_names[m] << " in ["
                    << rounded(k_min[m]) << ", " << rounded(k_max[m]) << "]";
              const std::string suffix = "_" + std::to_string(f + 1);
              statistics.add_value(std::string(mode_names[m]) + "_min" + suffix,
                                   k_min[m]);
              statistics.add_value(std::string(mode_names[m]) + "_max" + suffix,
                                   k_max[m]);
            }
          pcout << std::endl
                << "    |G - G_Irwin| / max G = " << std::setprecision(2)
                << std::round(irwin_gap / g_max * 1e4) * 1e-4
                << std::defaultfloat << std::endl;
          for (const auto &v : values)
            if (v.front == f && !v.crown_clear)
              {
                warn_crown(v);
                break;
              }
        }
    // Errors against the reference: relative to |K| where it does not
    // vanish (2D), or (3D) to the largest |K| of that mode along the front
    // (K_II and K_III vary in sign along a front under shear).
    if (reference_function)
      {
        double error[3] = {0, 0, 0};
        for (unsigned int m = 0; m < n_modes; ++m)
          {
            double scale = 0, overall = 0;
            for (unsigned int i = 0; i < values.size(); ++i)
              {
                scale   = std::max(scale, std::abs(reference[i][m]));
                overall = std::max(overall, reference[i].l2_norm());
              }
            for (unsigned int i = 0; i < values.size(); ++i)
              {
                double norm = (scale > 1e-12 * overall ? scale : overall);
                if (dim == 2)
                  norm = (std::abs(reference[i][m]) >
                              1e-12 * reference[i].l2_norm() ?
                            std::abs(reference[i][m]) :
                            reference[i].l2_norm());
                error[m] =
                  std::max(error[m],
                           std::abs(k_of(values[i], m) - reference[i][m]) /
                             norm);
              }
            statistics.add_value(std::string(mode_names[m]) + "_error",
                                 error[m]);
          }
        pcout << "  K errors against the reference (max over the "
              << (dim == 2 ? "tips" : "front")
              << ", to 1e-6): " << std::scientific << std::setprecision(3);
        for (unsigned int m = 0; m < n_modes; ++m)
          pcout << (m > 0 ? ", " : "") << mode_names[m] << " "
                << std::round(error[m] * 1e6) * 1e-6;
        pcout << std::defaultfloat << std::endl;
      }

    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        std::ofstream csv(run_parameters.output_directory + "/front_" +
                          Utilities::int_to_string(cycle, 3) + ".csv");
        csv << "index,s,x,y,z,K_I,K_II,K_III,G,G_Irwin,r_inf,r_sup,"
               "K_I_jump,K_II_jump,K_III_jump,front\n"
            << std::setprecision(10);
        for (unsigned int i = 0; i < values.size(); ++i)
          {
            const auto &v = values[i];
            csv << i << ',' << v.point.s << ',' << v.point.position[0] << ','
                << v.point.position[1] << ','
                << (dim == 3 ? v.point.position[dim - 1] : 0.) << ',' << v.k_I
                << ',' << v.k_II << ',' << v.k_III << ',' << v.g << ','
                << v.g_irwin << ',' << v.r_inf << ',' << v.r_sup << ','
                << jump_k[i][0] << ',' << jump_k[i][1] << ',' << jump_k[i][2]
                << ',' << v.front + 1 << '\n';
          }
      }
  }



  template <int dim>
  void
  ElasticityProblem<dim>::run()
  {
    // All input was checked in the constructor: from here on results are
    // written.
    timer = std::make_unique<TimerOutput>(mpi_communicator,
                                          pcout,
                                          TimerOutput::never,
                                          TimerOutput::wall_times);
    std::filesystem::create_directories(run_parameters.output_directory);
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      prm.print_parameters(run_parameters.output_directory + "/parameters.prm",
                           ParameterHandler::ShortPRM);

    pcout << "xcrack: " << dim << "D linear elasticity, Q" << degree
          << " elements, " << linear_solver.type << " solver" << std::endl;
    // Bilinear elements lock as the material becomes incompressible: the
    // answer stays finite but can be far off (Case 1 at nu = 0.499: 22 %
    // energy error with Q1 on 10,772 DoFs, 0.4 % with Q2 on 35,944).
    if (degree == 1 && material.poisson_ratio > 0.45)
      pcout << "Warning: Poisson's ratio = " << material.poisson_ratio
            << " with Degree = 1: bilinear elements lock when the material "
               "is nearly incompressible; use Discretization/Degree = 2."
            << std::endl;
    if (enrichment)
      {
        const auto &e = enrichment->get_parameters();
        pcout << "X-FEM: jump enrichment";
        if (e.tip_zone == EnrichmentParameters::TipZone::topological)
          pcout << ", branch functions on the nodes of the cells the front "
                   "touches";
        else if (e.tip_zone == EnrichmentParameters::TipZone::geometric)
          pcout << ", branch functions within " << e.radius << " of the front"
                << (e.gather ? ", gathered" : "");
        else
          pcout << " only (no branch functions)";
        pcout << std::endl;
      }

    std::map<std::string, double> previous_times;
    for (unsigned int cycle = 0; cycle < refinement.n_cycles; ++cycle)
      {
        if (cycle > 0)
          {
            TimerOutput::Scope t(*timer, "refine");
            refinement.refine(
              triangulation, dof_handler, solution, [&](const Point<dim> &p) {
                double distance = std::numeric_limits<double>::max();
                for (unsigned int c = 0; c < cracks.size(); ++c)
                  distance =
                    std::min(distance,
                             std::hypot(cracks[c].lsn(p), cracks[c].lst(p)));
                return distance;
              });
          }
        // The level-set fields give the crack as the mesh sees it (lips and
        // front, written and reported below); the enrichment still reads the
        // analytic geometry, which the fields interpolate (after the shifts
        // of fit to vertex: setup_system() updates them). Propagation will
        // update the fields every step.
        setup_system();
        assemble_system();
        const unsigned int iterations = solve();

        statistics.start_row();
        statistics.add_value("step", (unsigned long long)cycle);
        statistics.add_value("cycles", 0ull);
        statistics.add_value(
          "cells", (unsigned long long)triangulation.n_global_active_cells());
        statistics.add_value("dofs", (unsigned long long)dof_handler.n_dofs());
        statistics.add_value("enriched_dofs",
                             (unsigned long long)n_free_enriched_dofs());
        statistics.add_value("solver_iterations",
                             (unsigned long long)iterations);
        if (dof_handler.n_dofs() <= run_parameters.condition_number_limit)
          statistics.add_value("condition_number",
                               condition_number(system_matrix, constraints));

        pcout << "Cycle " << cycle << ": "
              << triangulation.n_global_active_cells() << " cells, "
              << dof_handler.n_dofs() << " dofs";
        if (linear_solver.type != "direct")
          pcout << ", " << iterations << " CG iterations";
        // The largest displacement component: a first sanity check of any
        // run (and what the demo compares with beam theory).
        const double max_displacement = compute_max_displacement();
        statistics.add_value("max_displacement", max_displacement);
        pcout << std::scientific << std::setprecision(4) << ", max |u_i| "
              << max_displacement << std::defaultfloat;
        if (exact_solution)
          {
            const auto [l2, energy] = compute_errors();
            statistics.add_value("L2_error", l2);
            statistics.add_value("energy_error", energy);
            pcout << std::scientific << std::setprecision(3) << ", L2 error "
                  << l2 << ", energy error " << energy << std::defaultfloat;
          }
        pcout << std::endl;
        if (enrichment && enrichment->get_parameters().gather)
          {
            const auto n_masters = enrichment->gathering_masters().n_elements();
            pcout << "  gathering: " << n_masters / (4 * dim) << " masters, "
                  << n_masters << " branch unknowns" << std::endl;
          }
        if (enrichment)
          report_crack_surface();
        if (enrichment && fracture_parameters.compute)
          compute_fracture_parameters(cycle);

        if (run_parameters.write_vtu)
          output_results(cycle);

        // Wall time of each phase in this cycle: the timer accumulates over
        // the run, so take differences.
        const auto times =
          timer->get_summary_data(TimerOutput::OutputData::total_wall_time);
        for (const std::string phase : {"setup",
                                        "assemble",
                                        "solve",
                                        "errors",
                                        "fracture",
                                        "output",
                                        "refine"})
          {
            const double total = (times.count(phase) ? times.at(phase) : 0.);
            statistics.add_value("t_" + phase, total - previous_times[phase]);
            previous_times[phase] = total;
          }
        if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
          statistics.write_csv(run_parameters.output_directory +
                               "/statistics.csv");
      }

    if (exact_solution && statistics.n_rows() > 1)
      print_convergence_table();
    if (run_parameters.timing_summary)
      timer->print_summary();
  }
} // namespace xcrack

#endif
