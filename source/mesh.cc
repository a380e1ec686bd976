#include <deal.II/distributed/tria.h>
#include <deal.II/grid/grid_generator.h>
#include <deal.II/grid/grid_in.h>

#include <xcrack/input_error.h>
#include <xcrack/mesh.h>
#include <xcrack/parsed_function.h>

#include <fstream>

namespace xcrack
{
  namespace
  {
    /// The unit cube.
    const std::string default_upper_corner = "1, 1, 1";
  } // namespace


  void
  MeshDescription::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    {
      prm.declare_entry("Type",
                        "box",
                        Patterns::Selection("box|generator|file"),
                        "Where the coarse mesh comes from: an axis-aligned "
                        "box, a deal.II GridGenerator function, or a file.");
      prm.declare_entry("Lower corner",
                        "0, 0, 0",
                        Patterns::Anything(),
                        "Box: comma-separated coordinates of the lower "
                        "corner (dim of them).");
      prm.declare_entry("Upper corner",
                        default_upper_corner,
                        Patterns::Anything(),
                        "Box: comma-separated coordinates of the upper "
                        "corner (dim of them).");
      prm.declare_entry("Subdivisions",
                        "1, 1, 1",
                        Patterns::Anything(),
                        "Box: number of coarse cells per direction (dim "
                        "positive integers). Choose them so that coarse cells "
                        "are close to cubes.");
      prm.declare_entry("Generator name",
                        "hyper_cube",
                        Patterns::Anything(),
                        "Generator: name of a GridGenerator function, e.g. "
                        "hyper_ball, plate_with_a_hole, hyper_shell.");
      prm.declare_entry("Generator arguments",
                        "0 : 1 : true",
                        Patterns::Anything(),
                        "Generator: the function's arguments separated by "
                        "':' (points as comma-separated coordinates), see "
                        "GridGenerator::generate_from_name_and_arguments.");
      prm.declare_entry("File name",
                        "",
                        Patterns::FileName(Patterns::FileName::input),
                        "File: the mesh file (Gmsh .msh, or a format GridIn "
                        "knows by its extension). A relative path is taken "
                        "from the directory of the parameter file that sets "
                        "it.");
      prm.declare_entry("Initial global refinement",
                        "0",
                        Patterns::Integer(0, 20),
                        "Number of global refinements of the coarse mesh.");
    }
    prm.leave_subsection();
  }



  void
  MeshDescription::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Mesh");
    {
      type                      = prm.get("Type");
      lower_corner              = prm.get("Lower corner");
      upper_corner              = prm.get("Upper corner");
      subdivisions              = prm.get("Subdivisions");
      generator_name            = prm.get("Generator name");
      generator_arguments       = prm.get("Generator arguments");
      file_name                 = prm.get("File name");
      initial_global_refinement = prm.get_integer("Initial global refinement");
    }
    prm.leave_subsection();

    if (type == "file")
      {
        check_input(!file_name.empty(),
                    "Mesh/File name is empty but Mesh/Type = file.");
        std::ifstream in(file_name);
        check_input(static_cast<bool>(in),
                    "Mesh/File name = " + file_name +
                      ": cannot open this file for reading (a relative name "
                      "is read from the directory of the parameter file "
                      "that sets it).");
      }
  }



  template <int dim>
  void
  MeshDescription::create(Triangulation<dim> &triangulation,
                          const bool          refine) const
  {
    if (type == "box")
      {
        const Point<dim> p1 =
          Point<dim>(parse_vector<dim>(lower_corner, "Mesh/Lower corner"));
        // (The default, the unit cube, serves in 2D as the unit square.)
        const Point<dim> p2 = Point<dim>(
          parse_vector<dim>(dim == 2 && upper_corner == default_upper_corner ?
                              "1, 1" :
                              upper_corner,
                            "Mesh/Upper corner"));
        for (unsigned int d = 0; d < dim; ++d)
          check_input(p1[d] < p2[d],
                      "Mesh/Lower corner and Mesh/Upper corner: coordinate " +
                        std::to_string(d) +
                        " of the lower corner must be smaller than that of "
                        "the upper corner.");

        const std::vector<std::string> parts =
          split_and_trim(subdivisions, ',');
        check_input(parts.size() >= dim,
                    "Mesh/Subdivisions = '" + subdivisions + "': expected " +
                      std::to_string(dim) + " positive integers.");
        std::vector<unsigned int> repetitions(dim);
        for (unsigned int d = 0; d < dim; ++d)
          {
            int n = 0;
            try
              {
                n = Utilities::string_to_int(parts[d]);
              }
            catch (...)
              {}
            check_input(n > 0,
                        "Mesh/Subdivisions = '" + subdivisions + "': '" +
                          parts[d] + "' is not a positive integer.");
            repetitions[d] = n;
          }
        GridGenerator::subdivided_hyper_rectangle(
          triangulation, repetitions, p1, p2, /*colorize=*/true);
      }
    else if (type == "generator")
      {
        try
          {
            GridGenerator::generate_from_name_and_arguments(
              triangulation, generator_name, generator_arguments);
          }
        catch (const std::exception &e)
          {
            const std::string detail = message_of(e);
            throw InputError("Mesh/Generator name = " + generator_name +
                             " with Mesh/Generator arguments = '" +
                             generator_arguments + "' failed in " +
                             std::to_string(dim) + "D. " + detail);
          }
      }
    else
      {
        GridIn<dim> grid_in(triangulation);
        try
          {
            grid_in.read(file_name);
          }
        catch (const std::exception &e)
          {
            const std::string detail = message_of(e);
            throw InputError("Mesh/File name = " + file_name +
                             ": cannot read a " + std::to_string(dim) +
                             "D mesh from this file. " + detail);
          }
      }

    if (refine)
      triangulation.refine_global(initial_global_refinement);
  }



  template void
  MeshDescription::create(Triangulation<2> &, const bool) const;
  template void
  MeshDescription::create(Triangulation<3> &, const bool) const;
} // namespace xcrack
