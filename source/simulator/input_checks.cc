#include <deal.II/base/mpi.h>

#include <xcrack/input_error.h>
#include <xcrack/simulator.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <unistd.h>

namespace xcrack
{
  // The checks of the input that need the mesh (called by the
  // constructor, before anything is written).

  template <int dim>
  void
  Simulator<dim>::check_loads()
  {
    // The data must be finite where it is used; how far it can move the
    // body tells a singular system by the size of its solution.
    {
      const BoundingBox<dim> box  = body_box();
      double                 size = 0;
      for (unsigned int d = 0; d < dim; ++d)
        size = std::max(size, box.side_length(d));
      displacement_scale = boundary_conditions.check_finite(
        triangulation, degree, size, material.youngs_modulus);
      if (!load_cycle.proportional())
        displacement_scale =
          std::max(displacement_scale,
                   load_cycle.minimum_loads().check_finite(
                     triangulation, degree, size, material.youngs_modulus));
      boundary_conditions.check_rigid_body_motions(triangulation, size);
    }
    check_input(!boundary_conditions.dirichlet.empty() ||
                  !boundary_conditions.pinned.empty(),
                "Boundary conditions/Dirichlet and Pinned points are empty: "
                "without any prescribed displacement the rigid body motions "
                "are free and the problem has no unique solution.");

    for (const BoundaryConditions<dim> *loads :
         {static_cast<const BoundaryConditions<dim> *>(&boundary_conditions),
          &load_cycle.minimum_loads()})
      check_input(!loads->lip_pressure || cracks.size() > 0,
                  loads->section +
                    "/Lip pressure is set but there is no crack (Cracks/"
                    "Number of cracks = 0).");
  }



  template <int dim>
  BoundingBox<dim>
  Simulator<dim>::body_box() const
  {
    Point<dim> low, high;
    for (unsigned int d = 0; d < dim; ++d)
      {
        low[d]  = std::numeric_limits<double>::max();
        high[d] = -low[d];
      }
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        for (const unsigned int v : cell->vertex_indices())
          for (unsigned int d = 0; d < dim; ++d)
            {
              low[d]  = std::min(low[d], cell->vertex(v)[d]);
              high[d] = std::max(high[d], cell->vertex(v)[d]);
            }
    for (unsigned int d = 0; d < dim; ++d)
      {
        low[d]  = Utilities::MPI::min(low[d], mpi_communicator);
        high[d] = Utilities::MPI::max(high[d], mpi_communicator);
      }
    return BoundingBox<dim>(std::make_pair(low, high));
  }



  template <int dim>
  void
  Simulator<dim>::check_crowns()
  {
    // A crown larger than the body covers all of it, every load and
    // support included: its K's are not those of the front. Radii given
    // as lengths are checked as they are; radii in cells against the
    // smallest cell the front can get (the finest cell of the initial
    // mesh refined to Maximum level), so that only crowns that cannot
    // fit are refused. Typically a unit slip (radii in mm in a body in m).
    if (!fracture_parameters.compute || cracks.size() == 0)
      return;
    const BoundingBox<dim> box      = body_box();
    const double           diagonal = box.get_boundary_points().first.distance(
      box.get_boundary_points().second);
    double smallest_unit = 1;
    if (fracture_parameters.crown_in_cells)
      {
        double h = std::numeric_limits<double>::max();
        for (const auto &cell : triangulation.active_cell_iterators())
          if (cell->is_locally_owned())
            h = std::min(
              h,
              cell->diameter() / std::sqrt(double(dim)) /
                std::pow(2.,
                         std::max(0,
                                  int(refinement_parameters.max_level) -
                                    cell->level())));
        smallest_unit = Utilities::MPI::min(h, mpi_communicator);
      }
    const double r_sup = fracture_parameters.crown_outer * smallest_unit;
    if (r_sup < diagonal)
      return;
    std::ostringstream message;
    message << "Fracture parameters/Crown radii: r_sup = "
            << fracture_parameters.crown_outer;
    if (fracture_parameters.crown_in_cells)
      message << " cells (at least " << r_sup
              << " on the finest cells Maximum level allows)";
    message << " is larger than the body, whose bounding box is " << diagonal
            << " across: the crown would cover all of it, its loads and "
               "supports included, and the K's would not be the front's. "
               "Give radii of a few cells near the front"
            << (fracture_parameters.crown_in_cells ?
                  "." :
                  " (Crown unit = absolute: they are lengths, in the "
                  "mesh's unit).");
    throw InputError(message.str());
  }



  template <int dim>
  void
  Simulator<dim>::check_cracks_seen()
  {
    // Each crack must be one the mesh sees: its level-set fields must cut
    // some cell along the crack (a crack inside a cell, whose lst is
    // positive at every vertex, or one along cell faces, is not there for
    // the enrichment, and its K would be meaningless). A resumed run's
    // cracks are its checkpoint's fields, on a mesh loaded later.
    if (cracks.size() > 0 && resume_directory.empty())
      {
        level_sets.initialize(cracks.shapes());
        for (unsigned int c = 0; c < cracks.size(); ++c)
          {
            CrackSurface<dim> surface;
            surface.extract(level_sets, c);
            // The measure is global: every rank takes this branch alike.
            if (surface.measure() > 0)
              continue;
            double h = 0;
            for (const auto &cell : triangulation.active_cell_iterators())
              if (cell->is_locally_owned())
                h = std::max(h, cell->diameter());
            h = Utilities::MPI::max(h, mpi_communicator);
            std::ostringstream message;
            message << "Cracks/Crack " << c + 1
                    << ": the mesh does not see this crack (no cell is cut "
                       "along it: it lies inside one cell or along cell "
                       "faces; the cells are up to "
                    << h
                    << " across). Refine the mesh there (Mesh/Initial global "
                       "refinement) or move the crack off the faces.";
            throw InputError(message.str());
          }
      }
  }



  template <int dim>
  void
  Simulator<dim>::check_output_directory()
  {
    // The output directory must be usable: this is the last check before
    // any result is written (creating it and a probe file touches no
    // earlier result).
    const std::filesystem::path dir(run_parameters.output_directory);
    check_input(!std::filesystem::exists(dir) ||
                  std::filesystem::is_directory(dir),
                "Output directory = " + run_parameters.output_directory +
                  ": exists and is not a directory.");
    unsigned int writable = 1;
    if (check_only && !std::filesystem::exists(dir))
      {
        // Creatable: the nearest directory above it that exists is
        // writable.
        std::filesystem::path above =
          std::filesystem::absolute(dir).parent_path();
        while (!std::filesystem::exists(above) && above.has_parent_path() &&
               above != above.parent_path())
          above = above.parent_path();
        check_input(std::filesystem::is_directory(above) &&
                      ::access(above.c_str(), W_OK) == 0,
                    "Output directory = " + run_parameters.output_directory +
                      ": cannot create it (" + above.string() +
                      " is not a writable directory).");
        return;
      }
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      {
        std::error_code error;
        std::filesystem::create_directories(dir, error);
        const std::filesystem::path probe = dir / ".xcrack-probe";
        writable = (!error && std::ofstream(probe).good());
        std::filesystem::remove(probe, error);
      }
    check_input(Utilities::MPI::min(writable, mpi_communicator) == 1,
                "Output directory = " + run_parameters.output_directory +
                  ": cannot create it or write into it (permissions?).");
    // No other run may write there while this one does (rank 0 holds the
    // lock; every rank learns whether it got it).
    std::string refused;
    if (Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
      try
        {
          output_lock =
            std::make_unique<DirectoryLock>(run_parameters.output_directory,
                                            "Output directory");
        }
      catch (const InputError &e)
        {
          refused = e.what();
        }
    refused = Utilities::MPI::broadcast(mpi_communicator, refused, 0);
    check_input(refused.empty(), refused);
  }



  template class Simulator<2>;
  template class Simulator<3>;
} // namespace xcrack
