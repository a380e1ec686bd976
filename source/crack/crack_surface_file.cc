#include <xcrack/crack/crack_surface_file.h>
#include <xcrack/input_error.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <map>
#include <sstream>

namespace xcrack
{
  namespace
  {
    std::string
    lower_extension(const std::string &file_name)
    {
      const auto  dot = file_name.find_last_of('.');
      std::string ext =
        (dot == std::string::npos ? std::string() : file_name.substr(dot));
      std::transform(ext.begin(), ext.end(), ext.begin(), [](char c) {
        return std::tolower(c);
      });
      return ext;
    }

    /**
     * Gmsh MSH 2.2 or 4.1, ASCII: nodes, and elements of types 1 (line),
     * 2 (triangle), 3 (quadrangle); other element types are skipped.
     */
    RawMesh
    read_msh(std::istream &in, const std::string &what)
    {
      RawMesh                        mesh;
      std::map<long, unsigned int>   index_of_tag;
      double                         version = 0;
      std::vector<std::vector<long>> cells;
      std::vector<int>               types;
      const auto                     fail = [&](const std::string &message) {
        throw InputError(what + ": " + message);
      };
      const auto element = [&](const int type, const std::vector<long> &nodes) {
        const std::map<int, unsigned int> n_nodes = {{1, 2}, {2, 3}, {3, 4}};
        if (n_nodes.count(type) == 0)
          return;
        if (nodes.size() < n_nodes.at(type))
          fail("an element of type " + std::to_string(type) +
               " lists too few nodes.");
        cells.emplace_back(nodes.begin(), nodes.begin() + n_nodes.at(type));
        types.push_back(type);
      };

      std::string token;
      while (in >> token)
        {
          if (token == "$MeshFormat")
            {
              int file_type = 0, data_size = 0;
              in >> version >> file_type >> data_size;
              if (!in || file_type != 0)
                fail("only ASCII Gmsh files are read (save with "
                     "'-format msh22' or 'msh41', not binary).");
              if (version < 2 || version >= 5)
                fail("Gmsh format version " + std::to_string(version) +
                     " is not supported (2.2 or 4.1 are).");
            }
          else if (token == "$Nodes")
            {
              if (version < 4)
                {
                  long n = 0;
                  in >> n;
                  for (long i = 0; i < n; ++i)
                    {
                      long                  tag;
                      std::array<double, 3> x;
                      in >> tag >> x[0] >> x[1] >> x[2];
                      index_of_tag[tag] = mesh.points.size();
                      mesh.points.push_back(x);
                    }
                }
              else
                {
                  long n_blocks = 0, n = 0, min_tag = 0, max_tag = 0;
                  in >> n_blocks >> n >> min_tag >> max_tag;
                  for (long b = 0; b < n_blocks && in; ++b)
                    {
                      int  entity_dim, entity_tag, parametric;
                      long n_in_block;
                      in >> entity_dim >> entity_tag >> parametric >>
                        n_in_block;
                      if (parametric != 0)
                        fail("nodes with parametric coordinates are not read "
                             "(save without them).");
                      std::vector<long> tags(n_in_block);
                      for (auto &t : tags)
                        in >> t;
                      for (const long t : tags)
                        {
                          std::array<double, 3> x;
                          in >> x[0] >> x[1] >> x[2];
                          index_of_tag[t] = mesh.points.size();
                          mesh.points.push_back(x);
                        }
                    }
                }
              if (!in)
                fail("the $Nodes section is truncated or malformed.");
            }
          else if (token == "$Elements")
            {
              std::string line;
              if (version < 4)
                {
                  long n = 0;
                  in >> n;
                  std::getline(in, line);
                  for (long i = 0; i < n && std::getline(in, line); ++i)
                    {
                      std::istringstream s(line);
                      long               id, type, n_tags;
                      s >> id >> type >> n_tags;
                      for (long t = 0, tag; t < n_tags; ++t)
                        s >> tag;
                      std::vector<long> nodes;
                      for (long v; s >> v;)
                        nodes.push_back(v);
                      element(type, nodes);
                    }
                }
              else
                {
                  long n_blocks = 0, n = 0, min_tag = 0, max_tag = 0;
                  in >> n_blocks >> n >> min_tag >> max_tag;
                  for (long b = 0; b < n_blocks && in; ++b)
                    {
                      int  entity_dim, entity_tag, type;
                      long n_in_block;
                      in >> entity_dim >> entity_tag >> type >> n_in_block;
                      std::getline(in, line);
                      for (long i = 0; i < n_in_block && std::getline(in, line);
                           ++i)
                        {
                          std::istringstream s(line);
                          long               id;
                          s >> id;
                          std::vector<long> nodes;
                          for (long v; s >> v;)
                            nodes.push_back(v);
                          element(type, nodes);
                        }
                    }
                }
              if (!in)
                fail("the $Elements section is truncated or malformed.");
            }
          else if (token.size() > 1 && token[0] == '$' &&
                   token.rfind("$End", 0) != 0)
            {
              // A section xcrack does not need ($Entities, $PhysicalNames...).
              const std::string end = "$End" + token.substr(1);
              while (in >> token && token != end)
                ;
            }
        }
      if (version == 0)
        fail("not a Gmsh file (no $MeshFormat section).");

      for (unsigned int c = 0; c < cells.size(); ++c)
        {
          std::vector<unsigned int> cell;
          for (const long tag : cells[c])
            {
              const auto it = index_of_tag.find(tag);
              if (it == index_of_tag.end())
                fail("an element refers to node " + std::to_string(tag) +
                     ", which the $Nodes section does not define.");
              cell.push_back(it->second);
            }
          (types[c] == 1 ? mesh.lines : mesh.polygons).push_back(cell);
        }
      return mesh;
    }

    /// Legacy ASCII VTK, POLYDATA (POLYGONS, LINES) or UNSTRUCTURED_GRID
    /// (cell types 3 line, 4 poly-line, 5 triangle, 7 polygon, 9 quad).
    RawMesh
    read_vtk(std::istream &in, const std::string &what)
    {
      RawMesh    mesh;
      const auto fail = [&](const std::string &message) {
        throw InputError(what + ": " + message);
      };
      std::string line;
      std::getline(in, line);
      if (line.find("vtk DataFile") == std::string::npos)
        fail("not a legacy VTK file (first line '" + line + "').");
      std::getline(in, line); // title
      std::string token;
      in >> token;
      if (token != "ASCII")
        fail("only ASCII VTK files are read, this one is " + token + ".");
      std::vector<std::vector<unsigned int>> cells;
      std::vector<int>                       types;
      bool                                   polydata = false;
      const auto read_lists = [&](std::vector<std::vector<unsigned int>> &to) {
        long n = 0, size = 0;
        in >> n >> size;
        for (long i = 0; i < n && in; ++i)
          {
            long k;
            in >> k;
            std::vector<unsigned int> list(k);
            for (auto &v : list)
              in >> v;
            to.push_back(list);
          }
      };
      while (in >> token)
        {
          if (token == "DATASET")
            {
              in >> token;
              if (token != "POLYDATA" && token != "UNSTRUCTURED_GRID")
                fail("DATASET " + token +
                     " is not read (POLYDATA or UNSTRUCTURED_GRID are).");
              polydata = (token == "POLYDATA");
            }
          else if (token == "POINTS")
            {
              long n;
              in >> n >> token;
              mesh.points.resize(n);
              for (auto &x : mesh.points)
                in >> x[0] >> x[1] >> x[2];
            }
          else if (token == "POLYGONS")
            read_lists(mesh.polygons);
          else if (token == "LINES")
            read_lists(mesh.lines);
          else if (token == "VERTICES")
            {
              std::vector<std::vector<unsigned int>> ignored;
              read_lists(ignored);
            }
          else if (token == "CELLS")
            read_lists(cells);
          else if (token == "CELL_TYPES")
            {
              long n;
              in >> n;
              types.resize(n);
              for (auto &t : types)
                in >> t;
            }
          else if (token == "OFFSETS" || token == "CONNECTIVITY")
            fail("VTK 5.1 offset/connectivity arrays are not read; save as "
                 "legacy VTK 4.2.");
          else if (token == "TRIANGLE_STRIPS")
            fail("triangle strips are not read; save triangles.");
          else if (token == "POINT_DATA" || token == "CELL_DATA")
            break;
          if (!in)
            fail("the section " + token + " is truncated or malformed.");
        }
      if (!polydata)
        {
          if (types.size() != cells.size())
            fail("CELLS and CELL_TYPES disagree on the number of cells.");
          for (unsigned int c = 0; c < cells.size(); ++c)
            if (types[c] == 3 || types[c] == 4)
              mesh.lines.push_back(cells[c]);
            else if (types[c] == 5 || types[c] == 7 || types[c] == 9)
              mesh.polygons.push_back(cells[c]);
        }
      for (const auto *lists : {&mesh.polygons, &mesh.lines})
        for (const auto &list : *lists)
          for (const unsigned int v : list)
            if (v >= mesh.points.size())
              fail("a cell refers to point " + std::to_string(v) + " of " +
                   std::to_string(mesh.points.size()) + ".");
      return mesh;
    }
  } // namespace



  RawMesh
  read_crack_surface_file(const std::string &file_name, const std::string &what)
  {
    std::ifstream in(file_name);
    check_input(static_cast<bool>(in),
                what +
                  ": cannot open this file for reading (a relative name is "
                  "read from the directory of the parameter file that sets "
                  "it).");
    const std::string ext = lower_extension(file_name);
    if (ext == ".msh")
      return read_msh(in, what);
    if (ext == ".vtk")
      return read_vtk(in, what);
    throw InputError(what + ": unknown extension '" + ext +
                     "'; crack surfaces are read from Gmsh (.msh) or "
                     "legacy VTK (.vtk) files.");
  }
} // namespace xcrack
