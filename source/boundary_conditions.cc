#include <deal.II/base/mpi.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/mapping_q1.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/vector.h>

#include <xcrack/boundary_conditions.h>
#include <xcrack/input_error.h>

#include <array>
#include <cmath>
#include <set>
#include <sstream>

namespace xcrack
{
  template <int dim>
  void
  BoundaryConditions<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Boundary conditions");
    {
      prm.declare_entry("Dirichlet",
                        "",
                        Patterns::Anything(),
                        "Prescribed displacements: items 'id: ux; uy[; uz]' "
                        "separated by '|'.");
      prm.declare_entry("Dirichlet components",
                        "",
                        Patterns::Anything(),
                        "Components prescribed on a Dirichlet boundary, as "
                        "items 'id: letters' separated by '|' (letters among "
                        "x, y, z). A boundary not listed has all components "
                        "prescribed.");
      prm.declare_entry("Neumann",
                        "",
                        Patterns::Anything(),
                        "Prescribed tractions (force per area, sigma.n): "
                        "items 'id: tx; ty[; tz]' separated by '|'.");
      prm.declare_entry("Body force",
                        "",
                        Patterns::Anything(),
                        "Force per volume 'fx; fy[; fz]'; empty for none.");
      prm.declare_entry("Lip pressure",
                        "",
                        Patterns::Anything(),
                        "Pressure on both lips of every crack (positive "
                        "pushes them apart), an expression of x, y[, z]; "
                        "empty for traction-free lips.");
      prm.declare_entry("Pinned points",
                        "",
                        Patterns::Anything(),
                        "Mesh vertices whose listed displacement components "
                        "are held at zero, to remove the rigid-body motions "
                        "when the loads are self-balanced tractions: items "
                        "'x, y[, z]: letters' separated by '|', e.g. "
                        "'0.5, -2: xy | 0.5, 2: x'.");
    }
    prm.leave_subsection();
  }



  namespace
  {
    /// Split 'id: value | id: value' into a map, naming @p entry in errors.
    std::map<types::boundary_id, std::string>
    parse_id_map(const std::string &text, const std::string &entry)
    {
      std::map<types::boundary_id, std::string> result;
      for (const std::string &item : split_and_trim(text, '|'))
        {
          const auto colon = item.find(':');
          check_input(colon != std::string::npos,
                      entry + ": item '" + item +
                        "' is not of the form 'boundary id: value'.");
          const std::string id_text = Utilities::trim(item.substr(0, colon));
          int               id      = -1;
          try
            {
              id = Utilities::string_to_int(id_text);
            }
          catch (...)
            {}
          check_input(id >= 0 && static_cast<types::boundary_id>(id) <
                                   numbers::internal_face_boundary_id,
                      entry + ": '" + id_text +
                        "' is not a valid boundary id (a non-negative "
                        "integer).");
          check_input(result.count(id) == 0,
                      entry + ": boundary id " + id_text +
                        " appears more than once.");
          result[id] = Utilities::trim(item.substr(colon + 1));
        }
      return result;
    }
  } // namespace



  template <int dim>
  void
  BoundaryConditions<dim>::parse_parameters(
    ParameterHandler                     &prm,
    const FunctionConstants              &constants,
    const std::shared_ptr<Function<dim>> &exact_solution)
  {
    prm.enter_subsection("Boundary conditions");
    const std::string dirichlet_text  = prm.get("Dirichlet");
    const std::string mask_text       = prm.get("Dirichlet components");
    const std::string neumann_text    = prm.get("Neumann");
    const std::string body_force_text = prm.get("Body force");
    const std::string pressure_text   = prm.get("Lip pressure");
    const std::string pinned_text     = prm.get("Pinned points");
    prm.leave_subsection();

    section                  = "Boundary conditions";
    const std::string prefix = section + "/";
    dirichlet.clear();
    neumann.clear();
    dirichlet_mask.clear();

    for (const auto &[id, expr] :
         parse_id_map(dirichlet_text, prefix + "Dirichlet"))
      {
        if (expr == "exact")
          {
            check_input(exact_solution != nullptr,
                        prefix + "Dirichlet: boundary " + std::to_string(id) +
                          " takes the exact solution, but the file gives "
                          "none (subsection Exact solution).");
            dirichlet[id] = exact_solution;
          }
        else
          dirichlet[id] = std::make_shared<ParsedVectorFunction<dim>>(
            expr,
            dim,
            constants,
            prefix + "Dirichlet (boundary " + std::to_string(id) + ")");
        dirichlet_mask[id] = ComponentMask(dim, true);
      }

    for (const auto &[id, letters] :
         parse_id_map(mask_text, prefix + "Dirichlet components"))
      {
        const std::string entry = prefix + "Dirichlet components";
        check_input(dirichlet.count(id) == 1,
                    entry + ": boundary id " + std::to_string(id) +
                      " has no Dirichlet data.");
        ComponentMask mask(dim, false);
        for (const char c : letters)
          {
            if (c == ' ' || c == ',')
              continue;
            const int d = c - 'x';
            check_input(d >= 0 && d < dim,
                        entry + ": '" + std::string(1, c) + "' (boundary " +
                          std::to_string(id) +
                          ") is not a displacement component of a " +
                          std::to_string(dim) + "D run (use x, y" +
                          (dim == 3 ? ", z" : "") + ").");
            mask.set(d, true);
          }
        check_input(mask.n_selected_components() > 0,
                    entry + ": boundary " + std::to_string(id) +
                      " selects no component.");
        dirichlet_mask[id] = mask;
      }

    for (const auto &[id, expr] :
         parse_id_map(neumann_text, prefix + "Neumann"))
      neumann[id] = std::make_unique<ParsedVectorFunction<dim>>(
        expr,
        dim,
        constants,
        prefix + "Neumann (boundary " + std::to_string(id) + ")");

    // A boundary with both kinds of data is fine only if the traction acts
    // on the components the displacement leaves free (a roller with a
    // tangential load, say). We cannot tell which traction components are
    // meant to be zero, so we reject the overlap only when the Dirichlet
    // data fixes every component: then the traction would be ignored.
    for (const auto &[id, f] : neumann)
      check_input(dirichlet.count(id) == 0 ||
                    dirichlet_mask.at(id).n_selected_components() < dim,
                  prefix + "Dirichlet and " + prefix + "Neumann: boundary id " +
                    std::to_string(id) +
                    " has both a full displacement and a traction; the "
                    "traction would be ignored.");

    body_force.reset();
    if (!Utilities::trim(body_force_text).empty())
      body_force = std::make_unique<ParsedVectorFunction<dim>>(
        body_force_text, dim, constants, prefix + "Body force");
    pinned.clear();
    for (const std::string &item : split_and_trim(pinned_text, '|'))
      {
        const auto colon = item.find(':');
        check_input(colon != std::string::npos,
                    prefix + "Pinned points: item '" + item +
                      "' is not of the form 'x, y[, z]: letters'.");
        const Point<dim> p(
          parse_vector<dim>(item.substr(0, colon), prefix + "Pinned points"));
        ComponentMask     mask(dim, false);
        const std::string letters = Utilities::trim(item.substr(colon + 1));
        for (const char c : letters)
          {
            const auto d = std::string("xyz").find(c);
            check_input(d != std::string::npos && d < dim,
                        prefix + "Pinned points: item '" + item +
                          "': components are letters among " +
                          std::string("xyz").substr(0, dim) + ".");
            mask.set(d, true);
          }
        check_input(mask.n_selected_components() > 0,
                    prefix + "Pinned points: item '" + item +
                      "' names no component.");
        pinned.emplace_back(p, mask);
      }

    lip_pressure.reset();
    if (!Utilities::trim(pressure_text).empty())
      lip_pressure = std::make_unique<ParsedVectorFunction<dim>>(
        pressure_text, 1, constants, prefix + "Lip pressure");
  }



  template <int dim>
  void
  BoundaryConditions<dim>::declare_load_set(ParameterHandler &prm)
  {
    prm.declare_entry("Dirichlet",
                      "",
                      Patterns::Anything(),
                      "Prescribed displacements, items 'id: ux; uy[; uz]' "
                      "separated by '|', on boundaries of Boundary "
                      "conditions/Dirichlet (the same components are held; "
                      "a boundary not listed holds zero displacement).");
    prm.declare_entry("Neumann",
                      "",
                      Patterns::Anything(),
                      "Tractions, items 'id: tx; ty[; tz]' separated by '|'.");
    prm.declare_entry("Body force",
                      "",
                      Patterns::Anything(),
                      "Force per volume 'fx; fy[; fz]'; empty for none.");
    prm.declare_entry("Lip pressure",
                      "",
                      Patterns::Anything(),
                      "Pressure on both lips of every crack, an expression "
                      "of x, y[, z]; empty for none.");
  }



  template <int dim>
  void
  BoundaryConditions<dim>::parse_load_set(ParameterHandler         &prm,
                                          const std::string        &set,
                                          const BoundaryConditions &supports,
                                          const FunctionConstants  &constants)
  {
    section                  = set;
    const std::string prefix = section + "/";
    dirichlet.clear();
    neumann.clear();
    dirichlet_mask = supports.dirichlet_mask;
    pinned         = supports.pinned;
    given          = false;
    for (const auto &[id, expr] :
         parse_id_map(prm.get("Dirichlet"), prefix + "Dirichlet"))
      {
        check_input(supports.dirichlet.count(id) == 1,
                    prefix + "Dirichlet: boundary " + std::to_string(id) +
                      " is not a Dirichlet boundary of " + supports.section +
                      "/Dirichlet (the supports are the same at every "
                      "instant of the load cycle; only their values "
                      "change).");
        dirichlet[id] = std::make_shared<ParsedVectorFunction<dim>>(
          expr,
          dim,
          constants,
          prefix + "Dirichlet (boundary " + std::to_string(id) + ")");
        given = true;
      }
    for (const auto &[id, function] : supports.dirichlet)
      if (dirichlet.count(id) == 0)
        dirichlet[id] = std::make_shared<Functions::ZeroFunction<dim>>(dim);
    for (const auto &[id, expr] :
         parse_id_map(prm.get("Neumann"), prefix + "Neumann"))
      {
        check_input(dirichlet_mask.count(id) == 0 ||
                      dirichlet_mask.at(id).n_selected_components() < dim,
                    prefix + "Neumann: boundary id " + std::to_string(id) +
                      " has a full displacement (" + supports.section +
                      "/Dirichlet); the traction would be ignored.");
        neumann[id] = std::make_unique<ParsedVectorFunction<dim>>(
          expr,
          dim,
          constants,
          prefix + "Neumann (boundary " + std::to_string(id) + ")");
        given = true;
      }
    body_force.reset();
    if (const std::string text = prm.get("Body force");
        !Utilities::trim(text).empty())
      {
        body_force = std::make_unique<ParsedVectorFunction<dim>>(
          text, dim, constants, prefix + "Body force");
        given = true;
      }
    lip_pressure.reset();
    if (const std::string text = prm.get("Lip pressure");
        !Utilities::trim(text).empty())
      {
        lip_pressure = std::make_unique<ParsedVectorFunction<dim>>(
          text, 1, constants, prefix + "Lip pressure");
        given = true;
      }
  }



  template <int dim>
  bool
  BoundaryConditions<dim>::empty() const
  {
    return !given;
  }



  template <int dim>
  void
  BoundaryConditions<dim>::check_against(
    const Triangulation<dim> &triangulation) const
  {
    const std::vector<types::boundary_id> local_ids =
      triangulation.get_boundary_ids();
    // On a distributed mesh each rank sees the ids of its own cells only.
    std::set<types::boundary_id> ids(local_ids.begin(), local_ids.end());
    const MPI_Comm               comm = triangulation.get_communicator();
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      {
        const auto all = Utilities::MPI::all_gather(comm, local_ids);
        for (const auto &v : all)
          ids.insert(v.begin(), v.end());
      }

    std::string known;
    for (const auto id : ids)
      known += (known.empty() ? "" : ", ") + std::to_string(id);

    const auto check = [&](const auto &map, const std::string &entry) {
      for (const auto &[id, f] : map)
        check_input(ids.count(id) == 1,
                    section + "/" + entry + ": boundary id " +
                      std::to_string(id) +
                      " does not exist on the mesh (its ids are " + known +
                      ").");
    };
    check(dirichlet, "Dirichlet");
    check(neumann, "Neumann");

    // A pinned point must be a vertex of the mesh (on some rank).
    for (const auto &[p, mask] : pinned)
      {
        bool found = false;
        for (const auto &cell : triangulation.active_cell_iterators())
          if (!cell->is_artificial())
            for (const unsigned int v : cell->vertex_indices())
              found =
                found || cell->vertex(v).distance(p) < 1e-10 * cell->diameter();
        std::ostringstream where;
        where << p;
        check_input(Utilities::MPI::logical_or(found, comm),
                    "Boundary conditions/Pinned points: (" + where.str() +
                      ") is not a vertex of the mesh.");
      }
  }



  template <int dim>
  double
  BoundaryConditions<dim>::check_finite(const Triangulation<dim> &triangulation,
                                        const unsigned int        degree,
                                        const double              size,
                                        const double youngs_modulus) const
  {
    // The first place some data is not finite on this rank.
    std::string culprit;
    double dirichlet_max = 0, traction_max = 0, force_max = 0, pressure_max = 0;
    Vector<double> value(dim);
    const auto     look = [&](const Function<dim> &f,
                          const Point<dim>    &x,
                          const std::string   &entry,
                          double              &largest,
                          const ComponentMask &mask = ComponentMask()) {
      f.vector_value(x, value);
      for (unsigned int c = 0; c < f.n_components; ++c)
        {
          if (mask.size() > 0 && !mask[c])
            continue;
          if (!std::isfinite(value(c)))
            {
              if (culprit.empty())
                {
                  std::ostringstream message;
                  message << entry << " is not finite at (" << x
                          << "), where it is used: " << value(c) << ".";
                  culprit = message.str();
                }
              return;
            }
          largest = std::max(largest, std::abs(value(c)));
        }
    };

    const QGauss<dim - 1> face_rule(degree + 1);
    const QGauss<dim>     cell_rule(degree + 1);
    const MappingQ1<dim>  mapping;
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          if (body_force)
            for (const auto &q : cell_rule.get_points())
              look(*body_force,
                   mapping.transform_unit_to_real_cell(cell, q),
                   section + "/Body force",
                   force_max);
          if (lip_pressure)
            for (const unsigned int v : cell->vertex_indices())
              {
                const double p = lip_pressure->value(cell->vertex(v));
                if (std::isfinite(p))
                  pressure_max = std::max(pressure_max, std::abs(p));
              }
          for (const auto &face : cell->face_iterators())
            {
              if (!face->at_boundary())
                continue;
              std::vector<Point<dim>> points;
              for (const unsigned int v : face->vertex_indices())
                points.push_back(face->vertex(v));
              for (const auto &q : face_rule.get_points())
                {
                  Point<dim> x;
                  for (const unsigned int v : face->vertex_indices())
                    x += GeometryInfo<dim - 1>::d_linear_shape_function(q, v) *
                         face->vertex(v);
                  points.push_back(x);
                }
              const auto id = face->boundary_id();
              const auto d  = dirichlet.find(id);
              if (d != dirichlet.end())
                for (const auto &x : points)
                  look(*d->second,
                       x,
                       section + "/Dirichlet (boundary " + std::to_string(id) +
                         ")",
                       dirichlet_max,
                       dirichlet_mask.at(id));
              const auto n = neumann.find(id);
              if (n != neumann.end())
                for (unsigned int i = face->n_vertices(); i < points.size();
                     ++i)
                  look(*n->second,
                       points[i],
                       section + "/Neumann (boundary " + std::to_string(id) +
                         ")",
                       traction_max);
            }
        }

    // Every rank stops with the first culprit any rank found.
    const MPI_Comm comm = triangulation.get_communicator();
    for (const std::string &message : Utilities::MPI::all_gather(comm, culprit))
      check_input(message.empty(), message);
    dirichlet_max = Utilities::MPI::max(dirichlet_max, comm);
    traction_max  = Utilities::MPI::max(traction_max, comm);
    force_max     = Utilities::MPI::max(force_max, comm);
    pressure_max  = Utilities::MPI::max(pressure_max, comm);
    return dirichlet_max +
           (traction_max + pressure_max) * size / youngs_modulus +
           force_max * size * size / youngs_modulus;
  }



  template <int dim>
  void
  BoundaryConditions<dim>::check_rigid_body_motions(
    const Triangulation<dim> &triangulation,
    const double              size) const
  {
    // No support at all has its own message (in the Simulator).
    if (dirichlet.empty() && pinned.empty())
      return;
    // The rigid-body motions: translations, then rotations about the
    // origin, scaled by the body's size so that all are of unit order.
    constexpr unsigned int n_modes = (dim == 2 ? 3 : 6);
    const auto mode = [size](const Point<dim> &x, const unsigned int k) {
      Tensor<1, dim> u;
      if (k < dim)
        u[k] = 1;
      else if (dim == 2)
        {
          u[0] = -x[1] / size;
          u[1] = x[0] / size;
        }
      else
        {
          // Rotations about z, x and y.
          const unsigned int axis = (k - dim + 2) % 3, a = (axis + 1) % 3,
                             b = (axis + 2) % 3;
          u[a]                 = -x[b] / size;
          u[b]                 = x[a] / size;
        }
      return u;
    };
    // Gram matrix of the held components: sum over held (vertex,
    // component) of the modes' values there, outer product.
    std::vector<double> gram(n_modes * n_modes, 0.);
    const auto hold = [&](const Point<dim> &x, const ComponentMask &mask) {
      std::array<Tensor<1, dim>, n_modes> u;
      for (unsigned int i = 0; i < n_modes; ++i)
        u[i] = mode(x, i);
      for (unsigned int c = 0; c < dim; ++c)
        if (mask.size() == 0 || mask[c])
          for (unsigned int i = 0; i < n_modes; ++i)
            for (unsigned int j = 0; j < n_modes; ++j)
              gram[i * n_modes + j] += u[i][c] * u[j][c];
    };
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto &face : cell->face_iterators())
          if (face->at_boundary() && dirichlet.count(face->boundary_id()))
            for (const unsigned int v : face->vertex_indices())
              hold(face->vertex(v), dirichlet_mask.at(face->boundary_id()));
    const MPI_Comm comm = triangulation.get_communicator();
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      for (const auto &[point, mask] : pinned)
        hold(point, mask);
    Utilities::MPI::sum(gram, comm, gram);

    LAPACKFullMatrix<double> matrix(n_modes, n_modes);
    for (unsigned int i = 0; i < n_modes; ++i)
      for (unsigned int j = 0; j < n_modes; ++j)
        matrix(i, j) = gram[i * n_modes + j];
    Vector<double>     eigenvalues;
    FullMatrix<double> modes;
    matrix.compute_eigenvalues_symmetric(-1., 1e300, 0., eigenvalues, modes);
    double largest = 0;
    for (const double e : eigenvalues)
      largest = std::max(largest, e);
    std::vector<std::string> free;
    const char              *about[3] = {"z", "x", "y"};
    for (unsigned int k = 0; k < eigenvalues.size(); ++k)
      if (eigenvalues(k) <= 1e-10 * largest)
        {
          // Name the motion by its largest part.
          unsigned int biggest = 0;
          for (unsigned int i = 1; i < n_modes; ++i)
            if (std::abs(modes(i, k)) > std::abs(modes(biggest, k)))
              biggest = i;
          free.push_back(
            biggest < dim ?
              std::string("a translation along ") + "xyz"[biggest] :
              std::string("a rotation about ") + about[biggest - dim]);
        }
    std::string list;
    for (unsigned int i = 0; i < free.size(); ++i)
      list += (i == 0 ? "" : (i + 1 == free.size() ? " and " : ", ")) + free[i];
    check_input(free.empty(),
                "Boundary conditions: the Dirichlet data and Pinned points "
                "leave the body free to move (" +
                  list +
                  "): hold it in every direction (Dirichlet components, "
                  "Pinned points).");
  }



  template class BoundaryConditions<2>;
  template class BoundaryConditions<3>;
} // namespace xcrack
