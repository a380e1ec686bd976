#ifndef xcrack_mesh_h
#define xcrack_mesh_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <deal.II/grid/tria.h>

#include <string>

namespace xcrack
{
  using namespace dealii;

  /**
   * Where the coarse mesh comes from (`subsection Mesh`):
   *
   * - `box`: a rectangle/box between two corners with a given number of
   *   subdivisions per direction. Boundary ids are 0/1 for the faces at the
   *   lower/upper x, 2/3 for y, 4/5 for z (GridGenerator's colorize rule).
   * - `generator`: any deal.II GridGenerator function by name, with its
   *   arguments in the colon-separated form of
   *   GridGenerator::generate_from_name_and_arguments().
   * - `file`: a Gmsh .msh (or any format GridIn guesses from the extension);
   *   boundary ids are the physical tags of the file.
   *
   * The mesh is then refined globally `Initial global refinement` times.
   */
  class MeshDescription
  {
  public:
    static void
    declare_parameters(ParameterHandler &prm);

    /**
     * Parse the entries and check what can be checked without the dimension
     * (the mesh file exists and is readable). Throws InputError.
     */
    void
    parse_parameters(ParameterHandler &prm);

    /**
     * Build the coarse mesh into @p triangulation and (with @p refine)
     * refine it globally.
     * Dimension-dependent errors (a corner with the wrong number of
     * coordinates, a generator that rejects its arguments, a file whose
     * cells are of another dimension) are thrown as InputError here.
     */
    template <int dim>
    void
    create(Triangulation<dim> &triangulation, const bool refine = true) const;

    std::string  type = "box";
    std::string  lower_corner;
    std::string  upper_corner;
    std::string  subdivisions;
    std::string  generator_name;
    std::string  generator_arguments;
    std::string  file_name;
    unsigned int initial_global_refinement = 0;
  };
} // namespace xcrack

#endif
