#ifndef xcrack_crack_crack_surface_file_h
#define xcrack_crack_crack_surface_file_h

#include <array>
#include <string>
#include <vector>

namespace xcrack
{
  /// What a crack surface file gave: points, and cells as lists of point
  /// indices (polygons: triangles and quadrilaterals; lines: segments).
  struct RawMesh
  {
    std::vector<std::array<double, 3>>     points;
    std::vector<std::vector<unsigned int>> polygons;
    std::vector<std::vector<unsigned int>> lines;
  };

  /**
   * Read the crack surface file @p file_name by its extension: Gmsh MSH 2.2
   * or 4.1 (ASCII, `.msh`) or legacy VTK (ASCII, `.vtk`, POLYDATA or
   * UNSTRUCTURED_GRID). An InputError names the file as @p what (the
   * entry and its value) when it cannot be opened or read.
   *
   * Hand-made rather than deal.II's GridIn: a crack is a soup of points and
   * cells, and GridIn (9.4) refuses the files crack meshes come in (a Gmsh
   * `$Comments` section, VTK POLYDATA) and builds a Triangulation, which a
   * crack surface does not need.
   */
  RawMesh
  read_crack_surface_file(const std::string &file_name,
                          const std::string &what);
} // namespace xcrack

#endif
