#include <deal.II/base/mpi.h>

#include <xcrack/boundary_conditions.h>
#include <xcrack/crack/crack_set.h>
#include <xcrack/exact_solution.h>
#include <xcrack/input_error.h>
#include <xcrack/linear_solver/interface.h>
#include <xcrack/material.h>
#include <xcrack/mesh.h>
#include <xcrack/parameters.h>
#include <xcrack/simulator.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <vector>

namespace xcrack
{
  void
  RunParameters::declare_parameters(ParameterHandler &prm)
  {
    prm.declare_entry("Dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "Space dimension of the run: 2 or 3.");
    prm.declare_entry("Output directory",
                      "output",
                      Patterns::DirectoryName(),
                      "Where results are written; created if missing. Files "
                      "of an earlier run are overwritten only once this run "
                      "has passed all its input checks.");
    prm.declare_entry("Function constants",
                      "",
                      Patterns::Anything(),
                      "Named constants for all expressions of the file, as "
                      "'name = value' items separated by ','. E, nu, mu, "
                      "lambda (from the material) and pi are always there.");
    prm.enter_subsection("Output");
    {
      prm.declare_entry("Write vtu",
                        "true",
                        Patterns::Bool(),
                        "Write solution-<step>.pvtu files and solution.pvd.");
      prm.declare_entry("Condition number up to dofs",
                        "0",
                        Patterns::Integer(0, 20000),
                        "Compute the condition number of the stiffness "
                        "matrix (dense eigenvalues, one MPI rank) for "
                        "problems of at most this many DoFs and write it to "
                        "statistics.csv as condition_number. 0: never.");
      prm.declare_entry("Timing summary",
                        "true",
                        Patterns::Bool(),
                        "Print the wall-time summary at the end of the run "
                        "and the wall times of the steps of a growth run "
                        "(tests switch it off to keep their output stable).");
      prm.declare_entry("Detailed screen",
                        "false",
                        Patterns::Bool(),
                        "A growth run prints one line per step; true adds "
                        "the detail of each solve (mesh, crack, K per tip or "
                        "front), as a static analysis prints it.");
    }
    prm.leave_subsection();
  }



  void
  RunParameters::parse_parameters(ParameterHandler &prm)
  {
    dimension        = prm.get_integer("Dimension");
    output_directory = prm.get("Output directory");
    check_input(!output_directory.empty(), "Output directory is empty.");

    user_constants.clear();
    for (const std::string &item :
         split_and_trim(prm.get("Function constants"), ','))
      {
        const auto eq = item.find('=');
        check_input(eq != std::string::npos,
                    "Function constants: item '" + item +
                      "' is not of the form 'name = value'.");
        const std::string name  = Utilities::trim(item.substr(0, eq));
        const std::string value = Utilities::trim(item.substr(eq + 1));
        check_input(!name.empty() && !std::isdigit(name[0]),
                    "Function constants: '" + name + "' is not a valid name.");
        try
          {
            user_constants[name] = Utilities::string_to_double(value);
          }
        catch (...)
          {
            throw InputError("Function constants: the value '" + value +
                             "' of " + name + " is not a number.");
          }
      }

    prm.enter_subsection("Output");
    {
      write_vtu              = prm.get_bool("Write vtu");
      timing_summary         = prm.get_bool("Timing summary");
      detailed_screen        = prm.get_bool("Detailed screen");
      condition_number_limit = prm.get_integer("Condition number up to dofs");
    }
    prm.leave_subsection();
  }



  void
  declare_all_parameters(ParameterHandler &prm)
  {
    RunParameters::declare_parameters(prm);
    MeshDescription::declare_parameters(prm);
    Material::declare_parameters(prm);
    // The declarations do not depend on the dimension.
    BoundaryConditions<3>::declare_parameters(prm);
    CrackSet<3>::declare_parameters(prm);
    prm.enter_subsection("Linear solver");
    LinearSolver::declare_parameters(prm);
    prm.leave_subsection();
    Simulator<3>::declare_parameters(prm);
    ExactSolution::declare_parameters(prm);
  }



  std::string
  message_of(const std::exception &e)
  {
    if (const auto *deal_exc = dynamic_cast<const ExceptionBase *>(&e))
      {
        std::ostringstream info;
        deal_exc->print_info(info);
        return Utilities::trim(info.str());
      }
    return e.what();
  }



  namespace
  {
    /**
     * ParameterHandler keeps the last of two `set` lines of one entry
     * without a word; a repeated entry is most often an edit that missed
     * the earlier line, so say which value wins (rank 0, on stderr).
     */
    void
    warn_about_repeated_entries(const std::string &text,
                                const std::string &filename)
    {
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        return;
      std::vector<std::string>            path;
      std::map<std::string, unsigned int> first_line;
      std::istringstream                  in(text);
      std::string                         line;
      for (unsigned int number = 1; std::getline(in, line); ++number)
        {
          line = Utilities::trim(line.substr(0, line.find('#')));
          if (line.rfind("subsection ", 0) == 0)
            path.push_back(Utilities::trim(line.substr(11)));
          else if (line == "end" && !path.empty())
            path.pop_back();
          else if (line.rfind("set ", 0) == 0)
            {
              const std::string::size_type equal = line.find('=');
              std::string                  key;
              for (const std::string &section : path)
                key += section + "/";
              key += Utilities::trim(line.substr(4, equal - 4));
              const auto [it, inserted] = first_line.emplace(key, number);
              if (!inserted)
                std::cerr << "Warning: " << filename << ": " << key
                          << " is set on lines " << it->second << " and "
                          << number << "; the value on line " << number
                          << " is used." << std::endl;
            }
        }
    }

    /**
     * ParameterHandler follows `include` lines (relative to the working
     * directory) without a guard: a file that includes itself, directly or
     * through others, recurses until the stack overflows. Follow the
     * chain first and name the cycle. Files that cannot be read are left
     * to ParameterHandler's message.
     */
    void
    check_include_cycles(const std::string        &filename,
                         std::vector<std::string> &chain)
    {
      std::error_code             error;
      const std::filesystem::path here =
        std::filesystem::weakly_canonical(filename, error);
      for (const std::string &link : chain)
        if (std::filesystem::weakly_canonical(link, error) == here)
          {
            std::string words;
            for (const std::string &name : chain)
              words += "'" + name + "' includes ";
            throw InputError("Parameter file '" + chain.front() +
                             "': includes run in a circle: " + words + "'" +
                             filename + "'.");
          }
      std::ifstream in(filename);
      if (!in)
        return;
      chain.push_back(filename);
      std::string line;
      while (std::getline(in, line))
        {
          line = Utilities::trim(line.substr(0, line.find('#')));
          if (line.rfind("include", 0) == 0 && line.size() > 7 &&
              std::isspace(static_cast<unsigned char>(line[7])))
            check_include_cycles(Utilities::trim(line.substr(7)), chain);
        }
      chain.pop_back();
    }
  } // namespace



  void
  read_parameter_file(ParameterHandler &prm, const std::string &filename)
  {
    check_input(!std::filesystem::is_directory(filename),
                "The parameter file '" + filename +
                  "' is a directory (to continue a run from its checkpoint: "
                  "xcrack --resume DIRECTORY).");
    std::ifstream in(filename);
    check_input(static_cast<bool>(in),
                "Cannot open the parameter file '" + filename + "'.");
    const std::string text((std::istreambuf_iterator<char>(in)),
                           std::istreambuf_iterator<char>());
    check_input(text.find("set ") != std::string::npos,
                "The parameter file '" + filename +
                  "' sets no entry (it is empty or holds only comments).");
    warn_about_repeated_entries(text, filename);
    std::vector<std::string> chain;
    check_include_cycles(filename, chain);
    try
      {
        std::istringstream stream(text);
        prm.parse_input(stream, filename);
      }
    catch (const std::exception &e)
      {
        throw InputError("Parameter file '" + filename + "': " + message_of(e));
      }
  }



  void
  read_parameter_string(ParameterHandler &prm, const std::string &content)
  {
    try
      {
        prm.parse_input_from_string(content, "", false);
      }
    catch (const std::exception &e)
      {
        throw InputError("Parameter input: " + message_of(e));
      }
  }
} // namespace xcrack
