#ifndef xcrack_elasticity_templates_h
#define xcrack_elasticity_templates_h

#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_tools.h>
#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/hp/fe_values.h>
#include <deal.II/lac/dynamic_sparsity_pattern.h>
#include <deal.II/lac/sparsity_tools.h>
#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/vector_tools.h>

#include <xcrack/condition_number.h>
#include <xcrack/elasticity.h>
#include <xcrack/exact_solution.h>
#include <xcrack/input_error.h>
#include <xcrack/output.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <set>

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
  }



  template <int dim>
  ElasticityProblem<dim>::ElasticityProblem(ParameterHandler &prm,
                                            const MPI_Comm    mpi_communicator)
    : mpi_communicator(mpi_communicator)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , prm(prm)
    , triangulation(mpi_communicator,
                    typename Triangulation<dim>::MeshSmoothing(
                      Triangulation<dim>::smoothing_on_refinement |
                      Triangulation<dim>::smoothing_on_coarsening))
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

    prm.enter_subsection("Discretization");
    degree = prm.get_integer("Degree");
    prm.leave_subsection();


    mesh_description.create(triangulation);
    boundary_conditions.check_against(triangulation);
    cracks.check_against(triangulation);
    check_input(!boundary_conditions.dirichlet.empty(),
                "Boundary conditions/Dirichlet is empty: without any "
                "prescribed displacement the rigid body motions are free and "
                "the problem has no unique solution.");

    check_input(cracks.size() <= 1,
                "Cracks/Number of cracks = " + std::to_string(cracks.size()) +
                  ": the X-FEM enrichment handles one crack for now.");
    if (cracks.size() == 1)
      {
        EnrichmentParameters enrichment_parameters;
        enrichment_parameters.parse_parameters(prm);
        enrichment = std::make_unique<Enrichment<dim>>(cracks[0],
                                                       degree,
                                                       enrichment_parameters);
        // Gauss rules per element: the cells of the tip zone carry the
        // non-polynomial branch functions and get two more points.
        for (const auto &fe : enrichment->get_fe_collection())
          {
            fe_collection.push_back(fe);
            quadrature_collection.push_back(
              QGauss<dim>(degree + (fe_collection.size() - 1 >=
                                        Enrichment<dim>::tip ?
                                      3 :
                                      1)));
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
    TimerOutput::Scope t(*timer, "setup");

    dof_handler.reinit(triangulation);
    if (enrichment)
      enrichment->set_fe_indices(dof_handler);
    dof_handler.distribute_dofs(fe_collection);
    enriched_dofs      = (enrichment ? enrichment->enriched_dofs(dof_handler) :
                                       IndexSet(dof_handler.n_dofs()));
    locally_owned_dofs = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant_dofs);

    constraints.clear();
    constraints.reinit(locally_relevant_dofs);
    DoFTools::make_hanging_node_constraints(dof_handler, constraints);
    if (enrichment)
      enrichment->make_constraints(dof_handler, constraints);

    make_dirichlet_constraints();
    constraints.close();

    DynamicSparsityPattern dsp(locally_relevant_dofs);
    DoFTools::make_sparsity_pattern(dof_handler, dsp, constraints, false);
    SparsityTools::distribute_sparsity_pattern(dsp,
                                               locally_owned_dofs,
                                               mpi_communicator,
                                               locally_relevant_dofs);
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
    level_sets.update(cracks);
  }



  template <int dim>
  void
  ElasticityProblem<dim>::make_dirichlet_constraints()
  {
    // Only the DoFs of owned cells need constraints, and only for them is
    // the enrichment known completely (their supports are owned or ghost).
    IndexSet locally_active_dofs;
    DoFTools::extract_locally_active_dofs(dof_handler, locally_active_dofs);

    // Interpolation treats enriched DoFs as nodal values, which they are
    // not: with unshifted enrichment the trace of u_h at a vertex is
    // s + sum_j phi_j(x) a_j (standard DoF s, enriched DoFs a_j, phi_j = H or
    // a branch function, evaluated on the side of the face). So where a
    // Dirichlet vertex carries free enriched DoFs we prescribe that sum: on
    // one side of the crack s = g - sum_j phi_j a_j; at a crack mouth, where
    // the data take two values g+ and g-, also the jump
    // sum_j (phi_j+ - phi_j-) a_j = g+ - g-, solved for the DoF with the
    // largest jump (the Heaviside DoF, a = (g+ - g-)/2, or F1's). Branch
    // DoFs stay free otherwise: Williams-type data is carried by them, and
    // zeroing them at the boundary would smear the singular field.
    struct BoundaryNode
    {
      std::vector<types::global_dof_index> enriched;
      std::vector<const Function<dim> *>   functions;
      /// Side of the crack (+1, -1) -> point just inside a face, data.
      std::map<int, std::pair<Point<dim>, double>> sides;
      /// Points of the Dirichlet faces around the vertex, with the weight
      /// (quadrature weight times the vertex's hat function) and the data.
      std::vector<std::tuple<Point<dim>, double, double>> samples;
      bool                                                branches = false;
    };
    std::map<types::global_dof_index, BoundaryNode> nodes; // by standard DoF
    std::set<types::global_dof_index>               partners;
    // In the hp space a vertex carries one copy of its DoFs per element
    // used around it; the hanging-node constraints tie the copies together
    // (dof = other) or set enriched copies to zero next to plain cells.
    // Work with the copy that stays free: invalid_dof_index if none does.
    const auto free_copy = [&](types::global_dof_index dof) {
      while (constraints.is_constrained(dof))
        {
          const auto *entries = constraints.get_constraint_entries(dof);
          if (entries->size() != 1 || (*entries)[0].second != 1. ||
              constraints.get_inhomogeneity(dof) != 0.)
            return numbers::invalid_dof_index;
          dof = (*entries)[0].first;
        }
      return dof;
    };
    if (enrichment)
      {
        std::vector<types::global_dof_index> dofs;
        const QGauss<dim - 1>                face_rule(3);
        const FE_Q<dim - 1>                  face_q1(1);
        Vector<double>                       g_sample(dim);
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (!cell->is_artificial() &&
              cell->active_fe_index() != Enrichment<dim>::plain)
            for (const auto &face : cell->face_iterators())
              {
                if (!face->at_boundary())
                  continue;
                const auto bc =
                  boundary_conditions.dirichlet.find(face->boundary_id());
                if (bc == boundary_conditions.dirichlet.end())
                  continue;
                const ComponentMask &mask =
                  boundary_conditions.dirichlet_mask.at(face->boundary_id());
                const FiniteElement<dim> &fe = cell->get_fe();
                const unsigned int        per_vertex = fe.n_dofs_per_vertex();
                dofs.resize(fe.n_dofs_per_cell());
                cell->get_dof_indices(dofs);
                for (const unsigned int fv : face->vertex_indices())
                  for (const unsigned int v : cell->vertex_indices())
                    if (cell->vertex_index(v) == face->vertex_index(fv))
                      {
                        // The boundary value of this face's side at the
                        // vertex: evaluate just inside the face.
                        const Point<dim> x =
                          face->vertex(fv) +
                          1e-10 * (face->center() - face->vertex(fv));
                        const int      side = (cracks[0].lsn(x) >= 0 ? 1 : -1);
                        Vector<double> g(dim);
                        bc->second->vector_value(x, g);
                        for (unsigned int i = v * per_vertex;
                             i < (v + 1) * per_vertex;
                             ++i)
                          {
                            const unsigned int c =
                              fe.system_to_component_index(i).first;
                            const types::global_dof_index standard =
                              free_copy(dofs[i]);
                            if (!mask[c] ||
                                Enrichment<dim>::is_enriched_dof(fe, i) ||
                                standard == numbers::invalid_dof_index)
                              continue;
                            BoundaryNode &node = nodes[standard];
                            for (unsigned int j = v * per_vertex;
                                 j < (v + 1) * per_vertex;
                                 ++j)
                              {
                                const types::global_dof_index a =
                                  free_copy(dofs[j]);
                                if (!Enrichment<dim>::is_enriched_dof(fe, j) ||
                                    fe.system_to_component_index(j).first !=
                                      c ||
                                    a == numbers::invalid_dof_index ||
                                    std::find(node.enriched.begin(),
                                              node.enriched.end(),
                                              a) != node.enriched.end())
                                  continue;
                                node.enriched.push_back(a);
                                node.functions.push_back(
                                  enrichment->enrichment_function(fe, j));
                              }
                            for (unsigned int j = v * per_vertex;
                                 j < (v + 1) * per_vertex;
                                 ++j)
                              if (Enrichment<dim>::is_enriched_dof(fe, j))
                                partners.insert(dofs[j]);
                            node.sides[side] = {x, g[c]};
                            for (unsigned int q = 0; q < face_rule.size(); ++q)
                              {
                                Point<dim> y;
                                for (const unsigned int w :
                                     face->vertex_indices())
                                  y += face_q1.shape_value(w,
                                                           face_rule.point(q)) *
                                       face->vertex(w);
                                bc->second->vector_value(y, g_sample);
                                node.samples.emplace_back(
                                  y,
                                  face_rule.weight(q) *
                                    face_q1.shape_value(fv,
                                                        face_rule.point(q)) *
                                    face->measure(),
                                  g_sample[c]);
                              }
                            for (const Function<dim> *f : node.functions)
                              node.branches =
                                node.branches ||
                                dynamic_cast<const BranchFunction<dim> *>(f);
                          }
                      }
              }
      }

    for (const auto &[id, function] : boundary_conditions.dirichlet)
      {
        std::map<types::global_dof_index, double> values;
        VectorTools::interpolate_boundary_values(
          dof_handler,
          id,
          *function,
          values,
          boundary_conditions.dirichlet_mask.at(id));
        for (const auto &[dof, value] : values)
          {
            if (constraints.is_constrained(dof) ||
                !locally_active_dofs.is_element(dof))
              continue;
            if (enriched_dofs.is_element(dof))
              {
                // Enriched vertex DoFs are handled with their standard
                // partner; others (Q2 edges) are not supported yet.
                check_input(partners.count(dof) == 1,
                            "Boundary conditions/Dirichlet: the crack reaches "
                            "boundary " +
                              std::to_string(id) +
                              ", which has prescribed displacements; with "
                              "degree 2 this is not supported yet.");
                continue;
              }
            const auto node = nodes.find(dof);
            if (node == nodes.end() || node->second.enriched.empty())
              {
                constraints.add_line(dof);
                constraints.set_inhomogeneity(dof, value);
                continue;
              }
            const BoundaryNode &n = node->second;
            if (n.branches)
              {
                constrain_by_local_fit(dof, n.enriched, n.functions, n.samples);
                continue;
              }
            // phi_j on each side, and the mean of the data.
            std::vector<double> mean(n.enriched.size(), 0.),
              jump(n.enriched.size(), 0.);
            double g_mean = 0, g_jump = 0;
            for (const auto &[side, data] : n.sides)
              {
                const double weight = 1. / n.sides.size();
                g_mean += weight * data.second;
                g_jump += side * data.second;
                for (unsigned int j = 0; j < n.enriched.size(); ++j)
                  {
                    const double phi = n.functions[j]->value(data.first);
                    mean[j] += weight * phi;
                    jump[j] += side * phi;
                  }
              }
            constraints.add_line(dof);
            for (unsigned int j = 0; j < n.enriched.size(); ++j)
              constraints.add_entry(dof, n.enriched[j], -mean[j]);
            constraints.set_inhomogeneity(dof, g_mean);
            if (n.sides.size() == 2)
              {
                unsigned int p = 0;
                for (unsigned int j = 1; j < jump.size(); ++j)
                  if (std::abs(jump[j]) > std::abs(jump[p]))
                    p = j;
                if (std::abs(jump[p]) > 1e-12 &&
                    !constraints.is_constrained(n.enriched[p]))
                  {
                    constraints.add_line(n.enriched[p]);
                    for (unsigned int j = 0; j < jump.size(); ++j)
                      if (j != p)
                        constraints.add_entry(n.enriched[p],
                                              n.enriched[j],
                                              -jump[j] / jump[p]);
                    constraints.set_inhomogeneity(n.enriched[p],
                                                  g_jump / jump[p]);
                  }
              }
          }
      }
  }



  template <int dim>
  void
  ElasticityProblem<dim>::constrain_by_local_fit(
    const types::global_dof_index                              standard,
    const std::vector<types::global_dof_index>                &enriched,
    const std::vector<const Function<dim> *>                  &functions,
    const std::vector<std::tuple<Point<dim>, double, double>> &samples)
  {
    // Least squares on the node's boundary patch: minimise
    // sum_q w_q (s + sum_j phi_j(x_q) a_j - g(x_q))^2 over (s, a), in
    // variables scaled to unit diagonal, with a small Tikhonov term on the
    // enriched ones: far from the front the branch functions are nearly
    // affine on a patch and the fit would otherwise be ill-posed.
    const unsigned int  m = 1 + enriched.size();
    FullMatrix<double>  matrix(m, m);
    Vector<double>      rhs(m), x(m);
    std::vector<double> phi(m);
    for (const auto &[point, weight, g] : samples)
      {
        phi[0] = 1;
        for (unsigned int j = 1; j < m; ++j)
          phi[j] = functions[j - 1]->value(point);
        for (unsigned int i = 0; i < m; ++i)
          {
            rhs(i) += weight * phi[i] * g;
            for (unsigned int j = 0; j < m; ++j)
              matrix(i, j) += weight * phi[i] * phi[j];
          }
      }
    std::vector<double> scale(m);
    for (unsigned int i = 0; i < m; ++i)
      scale[i] = (matrix(i, i) > 0 ? std::sqrt(matrix(i, i)) : 1.);
    for (unsigned int i = 0; i < m; ++i)
      {
        rhs(i) /= scale[i];
        for (unsigned int j = 0; j < m; ++j)
          matrix(i, j) /= scale[i] * scale[j];
        if (i > 0)
          matrix(i, i) += 1e-6;
      }
    matrix.gauss_jordan();
    matrix.vmult(x, rhs);

    constraints.add_line(standard);
    constraints.set_inhomogeneity(standard, x(0) / scale[0]);
    for (unsigned int j = 1; j < m; ++j)
      if (!constraints.is_constrained(enriched[j - 1]))
        {
          constraints.add_line(enriched[j - 1]);
          constraints.set_inhomogeneity(enriched[j - 1], x(j) / scale[j]);
        }
  }



  template <int dim>
  const FEValues<dim> &
  ElasticityProblem<dim>::reinit_fe_values(
    const typename DoFHandler<dim>::active_cell_iterator &cell,
    hp::FEValues<dim>                                    &hp_fe_values,
    std::unique_ptr<FEValues<dim>>                       &split_values,
    const unsigned int                                    n_points_1d) const
  {
    if (const Quadrature<dim> *rule =
          (enrichment ? enrichment->special_quadrature(cell, n_points_1d) :
                        nullptr))
      {
        split_values = std::make_unique<FEValues<dim>>(
          cell->get_fe(), *rule, hp_fe_values.get_update_flags());
        split_values->reinit(cell);
        return *split_values;
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
    std::unique_ptr<FEValues<dim>>       split_values;

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const FEValues<dim> &fe_values =
            reinit_fe_values(cell, hp_fe_values, split_values, degree + 1);
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
      error_quadrature.push_back(
        QGauss<dim>(degree + (enrichment && i >= Enrichment<dim>::tip ? 5 : 3)));
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
    std::unique_ptr<FEValues<dim>>           split_values;

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const FEValues<dim> &fe_values =
            reinit_fe_values(cell, hp_fe_values, split_values, degree + 3);
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
    if (enrichment)
      {
        const auto &e = enrichment->get_parameters();
        pcout << "X-FEM: jump enrichment";
        if (e.tip_zone == EnrichmentParameters::TipZone::topological)
          pcout << ", branch functions on the nodes of the cells the front "
                   "touches";
        else if (e.tip_zone == EnrichmentParameters::TipZone::geometric)
          pcout << ", branch functions within " << e.radius
                << " of the front";
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
            refinement.refine(triangulation, dof_handler, solution);
          }
        // The level-set fields are only written for now (enrichment reads the
        // crack geometry itself); propagation will update them every step.
        if (run_parameters.write_vtu)
          update_level_sets();
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

        if (run_parameters.write_vtu)
          output_results(cycle);

        // Wall time of each phase in this cycle: the timer accumulates over
        // the run, so take differences.
        const auto times =
          timer->get_summary_data(TimerOutput::OutputData::total_wall_time);
        for (const std::string phase :
             {"setup", "assemble", "solve", "errors", "output", "refine"})
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
