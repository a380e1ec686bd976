// Requirement: every kind of bad input stops the run at set-up with an
// InputError whose message names the culprit (entry, line, boundary id, file):
// unknown entries, wrong types, out-of-range values, malformed or
// inconsistent expressions, boundary ids absent from the mesh, impossible
// combinations (an enrichment radius that does not fit the tip zone, crowns
// larger than the body), a missing mesh file, an unusable output directory.
// A valid input is accepted, and so are crowns in cells that the refined
// front cells can fit.

#include <deal.II/base/mpi.h>

#include <xcrack/input_error.h>
#include <xcrack/parameters.h>
#include <xcrack/simulator.h>

#include <fstream>
#include <regex>

using namespace dealii;

std::ofstream logfile("output");

// A valid 2D input; each case below changes one thing in it.
const std::string valid = R"(set Dimension = 2
set Output directory = results
subsection Output
  set Write vtu = false
  set Timing summary = false
end
subsection Mesh
  set Type = box
  set Lower corner = 0, 0
  set Upper corner = 2, 1
  set Subdivisions = 2, 1
end
subsection Material
  set Poisson's ratio = 0.3
end
subsection Boundary conditions
  set Dirichlet = 0: 0; 0
  set Neumann = 1: 1; 0
end
)";

// A valid 3D input with a penny crack.
const std::string valid_3d = R"(set Dimension = 3
set Output directory = results
subsection Output
  set Write vtu = false
  set Timing summary = false
end
subsection Mesh
  set Lower corner = -1, -1, -1
  set Upper corner = 1, 1, 1
  set Subdivisions = 2, 2, 2
end
subsection Boundary conditions
  set Dirichlet = 4: 0; 0; 0
end
subsection Cracks
  set Number of cracks = 1
  subsection Crack 1
    set Shape = penny
    set Center = 0, 0, 0.1
    set Radius = 0.5
  end
end
)";

/// Set up a problem from @p input and print what happened.
void
check(const std::string &what, const std::string &input)
{
  logfile << what << ":\n  ";
  try
    {
      ParameterHandler prm;
      xcrack::declare_all_parameters(prm);
      xcrack::read_parameter_string(prm, input);
      if (prm.get_integer("Dimension") == 2)
        xcrack::Simulator<2> problem(prm);
      else
        xcrack::Simulator<3> problem(prm);
      logfile << "accepted" << std::endl;
    }
  catch (const xcrack::InputError &e)
    {
      logfile << e.what() << std::endl;
    }
}

/// @p input (by default the valid 2D input) with @p from replaced by @p to.
std::string
changed(const std::string &from,
        const std::string &to,
        const std::string &input = valid)
{
  const auto pos = input.find(from);
  AssertThrow(pos != std::string::npos, ExcMessage("no '" + from + "'"));
  return std::string(input).replace(pos, from.size(), to);
}

/// The valid 2D input with one segment crack given by @p entries.
std::string
with_crack(const std::string &entries)
{
  return valid +
         "subsection Cracks\n  set Number of cracks = 1\n"
         "  subsection Crack 1\n" +
         entries + "\n  end\nend\n";
}

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  {
    std::ofstream not_a_directory("a_file");
  }

  check("valid input", valid);
  check("unknown entry", changed("set Poisson's ratio", "set Poissons ratio"));
  check("wrong type", changed("ratio = 0.3", "ratio = abc"));
  check("out of range", changed("ratio = 0.3", "ratio = 0.5"));
  check("dimension out of range", changed("Dimension = 2", "Dimension = 4"));
  check("unknown subsection",
        changed("subsection Material", "subsection Materials"));
  check("unbalanced subsection", valid + "subsection Output\n");
  check("too few components",
        changed("Dirichlet = 0: 0; 0", "Dirichlet = 0: 0"));
  check("expression typo",
        changed("Dirichlet = 0: 0; 0", "Dirichlet = 0: sin(x; 0"));
  check("unknown variable", changed("Neumann = 1: 1; 0", "Neumann = 1: z; 0"));
  check("item without id", changed("Neumann = 1: 1; 0", "Neumann = 1; 0"));
  check("boundary id not on the mesh",
        changed("Neumann = 1: 1; 0", "Neumann = 7: 1; 0"));
  check("same id twice",
        changed("Dirichlet = 0: 0; 0", "Dirichlet = 0: 0; 0 | 0: 1; 1"));
  check("component letter of another dimension",
        changed("Dirichlet = 0: 0; 0",
                "Dirichlet = 0: 0; 0\nset Dirichlet components = 0: z"));
  check("full displacement and traction on one boundary",
        changed("Neumann = 1: 1; 0", "Neumann = 0: 1; 0"));
  check("roller with a traction is fine",
        changed("Dirichlet = 0: 0; 0",
                "Dirichlet = 0: 0; 0 | 1: 0; 0\n"
                "set Dirichlet components = 1: x"));
  check("no Dirichlet data", changed("Dirichlet = 0: 0; 0", "Dirichlet ="));
  check("body force with 3 components in 2D",
        changed("Neumann = 1: 1; 0",
                "Neumann = 1: 1; 0\nset Body force = 0; 0; -1"));
  check("reserved constant name", "set Function constants = E = 2\n" + valid);
  check("constant that is not a number",
        "set Function constants = a = two\n" + valid);
  check("missing mesh file",
        changed("set Type = box",
                "set Type = file\n  set File name = nowhere.msh"));
  check("box corners swapped",
        changed("set Upper corner = 2, 1", "set Upper corner = -2, 1"));
  check("subdivisions not positive",
        changed("set Subdivisions = 2, 1", "set Subdivisions = 2, 0"));
  check("too few coordinates",
        changed("set Lower corner = 0, 0", "set Lower corner = 0"));
  check("valid generator (colorized hyper_rectangle)",
        changed("set Type = box",
                "set Type = generator\n"
                "  set Generator name = hyper_rectangle\n"
                "  set Generator arguments = 0, 0 : 2, 1 : true"));
  check("bad generator arguments",
        changed("set Type = box",
                "set Type = generator\n"
                "  set Generator name = hyper_ball\n"
                "  set Generator arguments = 0 : 1"));
  check("bad refinement region",
        valid + "subsection Mesh refinement\n  set Strategy = region\n"
                "  subsection Region\n    set Region = 0.1 - r\n  end\nend\n");
  check("valid crack (edge crack from the left face)",
        with_crack("set Start point = -1, 0.5\nset End point = 0.7, 0.5\n"
                   "set Tips = end"));
  check("crack outside the body",
        with_crack("set Start point = 5, 5\nset End point = 6, 5"));
  check("crack tip outside the body",
        with_crack("set Start point = -1, 0.5\nset End point = 0.7, 0.5"));
  check("crack of zero length",
        with_crack("set Start point = 1, 0.5\nset End point = 1, 0.5"));
  check("3D shape in 2D", with_crack("set Shape = penny"));
  check("valid 3D penny", valid_3d);
  check("segment in 3D",
        changed("set Shape = penny", "set Shape = segment", valid_3d));
  check("penny outside the body",
        changed("set Center = 0, 0, 0.1", "set Center = 0, 0, 3", valid_3d));
  check("in-plane direction along the normal",
        changed("set Radius = 0.5",
                "set Radius = 0.5\nset In-plane direction = 0, 0, 2",
                valid_3d));
  check("negative radius",
        changed("set Radius = 0.5", "set Radius = -0.5", valid_3d));
  check("geometric tip enrichment without a radius",
        valid_3d + "subsection Enrichment\n  set Tip enrichment = geometric\n"
                   "end\n");
  check("enrichment radius with topological enrichment",
        valid_3d + "subsection Enrichment\n  set Enrichment radius = 0.2\n"
                   "end\n");
  check("pinned point that is not a vertex",
        valid + "subsection Boundary conditions\n"
                "  set Pinned points = 0.3, 0.33: xy\nend\n");
  check("pinned point with an unknown component",
        valid + "subsection Boundary conditions\n"
                "  set Pinned points = 0, 0: xq\nend\n");
  check("lip pressure without a crack",
        valid + "subsection Boundary conditions\n"
                "  set Lip pressure = 1\nend\n");
  check("reference K with three values in 2D",
        valid + "subsection Fracture parameters\n"
                "  set Reference K = 1; 0; 0\nend\n");
  const std::string k_tolerance =
    with_crack("set Start point = -1, 0.5\nset End point = 0.7, 0.5") +
    "subsection Mesh refinement\n  set Strategy = k tolerance\nend\n";
  check("k tolerance without a crack",
        valid + "subsection Mesh refinement\n"
                "  set Strategy = k tolerance\nend\n");
  check("k tolerance without the K error estimate", k_tolerance);
  check("k tolerance with a crown in cells",
        k_tolerance + "subsection Fracture parameters\n"
                      "  set Error estimate = true\nend\n");
  check("crown radii in the wrong order",
        valid + "subsection Fracture parameters\n"
                "  set Crown radii = 4, 2\nend\n");
  check("crown larger than the body (radii as lengths)",
        valid_3d + "subsection Fracture parameters\n"
                   "  set Crown unit = absolute\n"
                   "  set Crown radii = 1, 5\nend\n");
  check("crown larger than the body even on the finest cells",
        with_crack("set Start point = -1, 0.5\nset End point = 0.7, 0.5\n"
                   "set Tips = end") +
          "subsection Mesh refinement\n  set Maximum level = 3\nend\n"
          "subsection Fracture parameters\n"
          "  set Crown radii = 2, 100\nend\n");
  check("crown as large as the body on the initial cells only",
        with_crack("set Start point = -1, 0.5\nset End point = 0.7, 0.5\n"
                   "set Tips = end") +
          "subsection Fracture parameters\n"
          "  set Crown radii = 2, 10\nend\n");
  check("crack mesh file that does not exist",
        with_crack("    set Shape = mesh\n    set File name = nowhere.msh"));
  check("output directory is a file",
        changed("Output directory = results", "Output directory = a_file"));
}
