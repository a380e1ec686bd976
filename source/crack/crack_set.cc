#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <deal.II/grid/grid_tools.h>

#include <xcrack/crack/crack_set.h>
#include <xcrack/crack/facet_crack.h>
#include <xcrack/crack/mesh_crack.h>
#include <xcrack/input_error.h>
#include <xcrack/parsed_function.h>

#include <algorithm>
#include <limits>
#include <sstream>

namespace xcrack
{
  namespace
  {
    double
    parse_positive(const std::string &text, const std::string &entry)
    {
      const double value = parse_numbers(text, 1, entry)[0];
      check_input(value > 0, entry + " = " + text + ": must be positive.");
      return value;
    }
  } // namespace



  template <int dim>
  void
  CrackSet<dim>::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Cracks");
    {
      prm.declare_entry("Number of cracks",
                        "0",
                        Patterns::Integer(0, max_cracks),
                        "Number of cracks, each described in its own "
                        "subsection 'Crack <i>', i = 1, 2, ... Several "
                        "cracks share the enriched space as long as their "
                        "enriched zones stay at least a cell apart (no "
                        "crossing or branching); the run stops with an "
                        "error naming both cracks where they meet.");
      for (unsigned int i = 1; i <= max_cracks; ++i)
        {
          prm.enter_subsection("Crack " + std::to_string(i));
          prm.declare_entry(
            "Shape",
            "segment",
            Patterns::Selection(
              "segment|half plane|penny|ellipse|rectangle|mesh"),
            "2D: segment or mesh. 3D: half plane, penny, "
            "ellipse, rectangle or mesh (a crack surface "
            "mesh read from 'File name').");
          prm.declare_entry("Start point",
                            "0, 0",
                            Patterns::Anything(),
                            "Segment: first end.");
          prm.declare_entry("End point",
                            "1, 0",
                            Patterns::Anything(),
                            "Segment: second end. The crack normal is "
                            "(end - start) rotated by +90 degrees.");
          prm.declare_entry("Tips",
                            "both",
                            Patterns::Selection("both|end|start|none"),
                            "Segment: which ends are crack tips; the others "
                            "are mouths on (or beyond) the boundary; none: "
                            "the crack splits the body.");
          prm.declare_entry("Center",
                            "0, 0, 0",
                            Patterns::Anything(),
                            "3D: centre of the penny, ellipse or rectangle; "
                            "for a half plane, a point of its front.");
          prm.declare_entry("Normal",
                            "0, 0, 1",
                            Patterns::Anything(),
                            "3D: normal of the crack plane (the lsn > 0 "
                            "side).");
          prm.declare_entry("In-plane direction",
                            "1, 0, 0",
                            Patterns::Anything(),
                            "3D: half plane: direction e1 in which the "
                            "front advances (the crack lies behind it); "
                            "ellipse: major axis (semi-axis a); rectangle: "
                            "direction of the width.");
          prm.declare_entry("Radius", "1", Patterns::Anything(), "Penny.");
          prm.declare_entry("Semi-axes",
                            "1, 0.5",
                            Patterns::Anything(),
                            "Ellipse: a (along the in-plane direction), b.");
          prm.declare_entry("Size",
                            "1, 1",
                            Patterns::Anything(),
                            "Rectangle: width (along the in-plane "
                            "direction), height.");
          prm.declare_entry(
            "File name",
            "",
            Patterns::FileName(Patterns::FileName::input),
            "Mesh: the crack surface, triangles or quadrilaterals in 3D, "
            "line segments in 2D, in a Gmsh (.msh, ASCII 2.2 or 4.1) or "
            "legacy VTK (.vtk, ASCII) file. Its boundary is the front where "
            "it lies inside the body and a mouth elsewhere. Or the surface "
            "an earlier run's `crack mesh` level-set update wrote "
            "(crack_mesh-<step>.vtu): its facets and fronts as they were, "
            "and that update grows it on. A relative path is taken from the "
            "directory of the parameter file that sets it.");
          prm.declare_entry(
            "Level set band",
            "0",
            Patterns::Double(0),
            "Mesh: level sets by projection only within this distance of "
            "the crack's bounding box (0: everywhere); farther nodes get "
            "the side of the crack only. Keep it several cells wide.");
          prm.leave_subsection();
        }
    }
    prm.leave_subsection();
  }



  namespace
  {
    /// Whether @p file_name is a surface the `crack mesh` update wrote (a
    /// .vtu file).
    bool
    is_facet_file(const std::string &file_name)
    {
      return file_name.size() > 4 &&
             file_name.compare(file_name.size() - 4, 4, ".vtu") == 0;
    }

    /// The crack described by the current subsection of @p prm; @p name
    /// prefixes the entries in error messages.
    template <int dim>
    std::unique_ptr<CrackGeometry<dim>>
    create_crack(ParameterHandler &prm, const std::string &name);

    template <>
    std::unique_ptr<CrackGeometry<2>>
    create_crack(ParameterHandler &prm, const std::string &name)
    {
      const std::string shape = prm.get("Shape");
      if (shape == "mesh" && is_facet_file(prm.get("File name")))
        return std::make_unique<FacetCrack<2>>(prm.get("File name"),
                                               name + "File name");
      if (shape == "mesh")
        return std::make_unique<MeshCrack<2>>(prm.get("File name"),
                                              name + "File name",
                                              prm.get_double("Level set band"));
      check_input(shape == "segment",
                  name + "Shape = " + shape +
                    ": a 2D run supports the shapes 'segment' and 'mesh'.");
      const Point<2> start =
        Point<2>(parse_vector<2>(prm.get("Start point"), name + "Start point"));
      const Point<2> end =
        Point<2>(parse_vector<2>(prm.get("End point"), name + "End point"));
      check_input((end - start).norm() > 0,
                  name + "Start point and " + name +
                    "End point: the segment has zero length.");
      const std::string tips = prm.get("Tips");
      return std::make_unique<SegmentCrack>(start,
                                            end,
                                            tips == "both" || tips == "start",
                                            tips == "both" || tips == "end");
    }

    template <>
    std::unique_ptr<CrackGeometry<3>>
    create_crack(ParameterHandler &prm, const std::string &name)
    {
      const std::string shape = prm.get("Shape");
      check_input(shape != "segment",
                  name + "Shape = segment: a 3D run needs a surface "
                         "(half plane, penny, ellipse, rectangle, mesh).");
      if (shape == "mesh" && is_facet_file(prm.get("File name")))
        return std::make_unique<FacetCrack<3>>(prm.get("File name"),
                                               name + "File name");
      if (shape == "mesh")
        return std::make_unique<MeshCrack<3>>(prm.get("File name"),
                                              name + "File name",
                                              prm.get_double("Level set band"));
      const Point<3> center =
        Point<3>(parse_vector<3>(prm.get("Center"), name + "Center"));
      const Tensor<1, 3> normal =
        parse_vector<3>(prm.get("Normal"), name + "Normal");
      const Tensor<1, 3> direction =
        parse_vector<3>(prm.get("In-plane direction"),
                        name + "In-plane direction");
      check_input(normal.norm() > 0, name + "Normal is the zero vector.");
      check_input(cross_product_3d(normal, direction).norm() >
                    1e-6 * normal.norm() * direction.norm(),
                  name + "In-plane direction is zero or parallel to " + name +
                    "Normal: it must lie in the crack plane.");

      if (shape == "half plane")
        return std::make_unique<HalfPlaneCrack>(center, normal, direction);
      else if (shape == "penny")
        {
          const double r = parse_positive(prm.get("Radius"), name + "Radius");
          return std::make_unique<EllipticalCrack>(
            center, normal, direction, r, r);
        }
      else if (shape == "ellipse")
        {
          const std::vector<double> ab =
            parse_numbers(prm.get("Semi-axes"), 2, name + "Semi-axes");
          check_input(ab[0] > 0 && ab[1] > 0,
                      name + "Semi-axes: both must be positive.");
          return std::make_unique<EllipticalCrack>(
            center, normal, direction, ab[0], ab[1]);
        }
      else
        {
          const std::vector<double> size =
            parse_numbers(prm.get("Size"), 2, name + "Size");
          check_input(size[0] > 0 && size[1] > 0,
                      name + "Size: width and height must be positive.");
          return std::make_unique<RectangularCrack>(
            center, normal, direction, size[0], size[1]);
        }
    }
  } // namespace



  template <int dim>
  void
  CrackSet<dim>::parse_parameters(ParameterHandler &prm)
  {
    cracks.clear();
    prm.enter_subsection("Cracks");
    const unsigned int n = prm.get_integer("Number of cracks");
    for (unsigned int i = 1; i <= n; ++i)
      {
        prm.enter_subsection("Crack " + std::to_string(i));
        cracks.push_back(
          create_crack<dim>(prm, "Cracks/Crack " + std::to_string(i) + "/"));
        prm.leave_subsection();
      }
    prm.leave_subsection();
  }



  template <int dim>
  void
  CrackSet<dim>::check_against(
    const parallel::distributed::Triangulation<dim> &mesh)
  {
    for (auto &crack : cracks)
      crack->locate_in(mesh);

    const MPI_Comm comm = mesh.get_communicator();
    // The coarse cells, present on every rank, span the whole body.
    const BoundingBox<dim> body = GridTools::compute_bounding_box(mesh);

    for (unsigned int i = 0; i < cracks.size(); ++i)
      {
        const std::string name = "Cracks/Crack " + std::to_string(i + 1);
        const CrackGeometry<dim> &crack = *cracks[i];

        // A cell is cut if lsn changes sign over it and the crack reaches
        // it: lst below the cell size at some vertex (not below zero, so
        // that a crack smaller than a cell still counts).
        bool cuts_a_cell = false;
        for (const auto &cell : mesh.active_cell_iterators())
          if (cell->is_locally_owned() && !cuts_a_cell)
            {
              double min_lsn = std::numeric_limits<double>::max();
              double max_lsn = -min_lsn, min_lst = min_lsn;
              for (const unsigned int v : cell->vertex_indices())
                {
                  const double n = crack.lsn(cell->vertex(v));
                  min_lsn        = std::min(min_lsn, n);
                  max_lsn        = std::max(max_lsn, n);
                  min_lst = std::min(min_lst, crack.lst(cell->vertex(v)));
                }
              cuts_a_cell =
                (min_lsn <= 0 && max_lsn >= 0 && min_lst < cell->diameter());
            }
        check_input(Utilities::MPI::logical_or(cuts_a_cell, comm),
                    name + ": the crack does not cut the mesh; is it "
                           "outside the body?");

        if (dim == 2)
          for (const FrontPoint<dim> &tip : crack.front(0, body))
            {
              bool inside = false;
              for (const auto &cell : mesh.active_cell_iterators())
                if (cell->is_locally_owned() &&
                    cell->point_inside(tip.position))
                  {
                    inside = true;
                    break;
                  }
              std::ostringstream where;
              where << tip.position;
              check_input(Utilities::MPI::logical_or(inside, comm),
                          name + ": the tip at (" + where.str() +
                            ") lies outside the body. If this end is a "
                            "mouth on the boundary, say so with 'Tips'.");
              // A tip on the boundary is not a tip: the crack opens there
              // (and a crown around it would leave the body).
              bool on_boundary = false;
              for (const auto &cell : mesh.active_cell_iterators())
                if (cell->is_locally_owned() && cell->at_boundary())
                  for (const auto &face : cell->face_iterators())
                    if (face->at_boundary())
                      {
                        const Point<dim>     a = face->vertex(0);
                        const Tensor<1, dim> e = face->vertex(1) - a;
                        const double         w =
                          std::clamp((tip.position - a) * e / e.norm_square(),
                                     0.,
                                     1.);
                        on_boundary =
                          on_boundary || tip.position.distance(a + w * e) <=
                                           1e-8 * cell->diameter();
                      }
              check_input(!Utilities::MPI::logical_or(on_boundary, comm),
                          name + ": the tip at (" + where.str() +
                            ") lies on the boundary of the body, where the "
                            "crack opens: that end is a mouth, say so with "
                            "'Tips'.");
            }
      }
  }



  template <int dim>
  unsigned int
  CrackSet<dim>::size() const
  {
    return cracks.size();
  }



  template <int dim>
  const CrackGeometry<dim> &
  CrackSet<dim>::operator[](const unsigned int i) const
  {
    return *cracks[i];
  }



  template <int dim>
  std::vector<const CrackGeometry<dim> *>
  CrackSet<dim>::shapes() const
  {
    std::vector<const CrackGeometry<dim> *> list;
    for (const auto &crack : cracks)
      list.push_back(crack.get());
    return list;
  }



  template class CrackSet<2>;
  template class CrackSet<3>;
} // namespace xcrack
