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

#include <algorithm>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <regex>
#include <set>
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



  void
  print_parameters(const ParameterHandler             &prm,
                   std::ostream                       &out,
                   const ParameterHandler::OutputStyle style)
  {
    std::ostringstream text;
    prm.print_parameters(text, style);
    const std::regex repeated("Crack ([2-9]|[1-9][0-9]+)");
    if (style == ParameterHandler::JSON)
      {
        boost::property_tree::ptree tree;
        std::istringstream          in(text.str());
        boost::property_tree::read_json(in, tree);
        const boost::property_tree::ptree::path_type cracks("Cracks", '\0');
        if (auto section = tree.get_child_optional(cracks))
          for (auto it = section->begin(); it != section->end();)
            it = (std::regex_match(it->first, repeated) ? section->erase(it) :
                                                          std::next(it));
        boost::property_tree::write_json(out, tree);
        return;
      }
    // PRM: drop the blocks `subsection Crack <n>` of n >= 2, and say once
    // that they repeat Crack 1.
    std::istringstream in(text.str());
    std::string        line;
    unsigned int       skipping = 0;
    bool               noted    = false;
    while (std::getline(in, line))
      {
        const std::string statement = Utilities::trim(line);
        if (skipping > 0)
          {
            if (statement.rfind("subsection ", 0) == 0)
              ++skipping;
            else if (statement == "end")
              --skipping;
            continue;
          }
        if (statement.rfind("subsection ", 0) == 0 &&
            std::regex_match(Utilities::trim(statement.substr(11)), repeated))
          {
            skipping = 1;
            if (!noted)
              out << line.substr(0, line.find("subsection"))
                  << "# subsection Crack 2, Crack 3, ...: the entries of "
                     "Crack 1, one subsection per crack\n";
            noted = true;
            continue;
          }
        out << line << '\n';
      }
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
    namespace fs = std::filesystem;

    /// Where a line of an expanded parameter file comes from.
    struct Origin
    {
      /// The file as the user named it (on the command line, or as the
      /// include line names it).
      std::string  file;
      unsigned int line = 0;

      std::string
      text() const
      {
        return "'" + file + "', line " + std::to_string(line);
      }
    };

    /// A parameter file with its includes put in place: every line with
    /// where it comes from.
    struct ExpandedFile
    {
      std::vector<std::string> lines;
      std::vector<Origin>      origins;
    };

    /**
     * The paths ("Mesh/File name") of the entries of @p prm declared with
     * Patterns::FileName: the names a parameter file resolves relative to
     * its own directory.
     */
    std::set<std::string>
    file_name_entries(const ParameterHandler &prm)
    {
      std::ostringstream text;
      prm.print_parameters(text, ParameterHandler::JSON);
      boost::property_tree::ptree tree;
      std::istringstream          in(text.str());
      boost::property_tree::read_json(in, tree);
      std::set<std::string> names;
      const std::function<void(const boost::property_tree::ptree &,
                               const std::string &)>
        walk = [&](const boost::property_tree::ptree &node,
                   const std::string                 &path) {
          for (const auto &[key, child] : node)
            {
              const auto pattern = child.get_child_optional(
                boost::property_tree::ptree::path_type("pattern_description",
                                                       '\0'));
              if (pattern)
                {
                  if (pattern->data().rfind("[FileName", 0) == 0)
                    names.insert(path + key);
                }
              else
                walk(child, path + key + "/");
            }
        };
      walk(tree, "");
      return names;
    }

    /// @p line without its comment, trimmed.
    std::string
    statement(const std::string &line)
    {
      return Utilities::trim(line.substr(0, line.find('#')));
    }

    /// The file @p name (as an include or an entry gives it) relative to
    /// the directory of the parameter file @p from.
    fs::path
    relative_to(const std::string &name, const std::string &from)
    {
      const fs::path path(name);
      if (path.is_absolute())
        return path;
      return (fs::absolute(from).parent_path() / path).lexically_normal();
    }

    /**
     * Append @p filename, its includes put in place, to @p expanded. An
     * include names a file relative to the directory of the file that holds
     * it, and so does every entry in @p file_entries: their relative values
     * become absolute, so that a scene runs from any directory and a
     * resumed run finds them again. @p sections is the subsection path at
     * the include; @p chain the files being included, to name a circle.
     */
    void
    expand(const std::string              &filename,
           const std::set<std::string>    &file_entries,
           std::vector<std::string>       &sections,
           std::vector<std::string>       &chain,
           const std::vector<std::string> &shown_chain,
           ExpandedFile                   &expanded)
    {
      std::error_code error;
      const fs::path  here = fs::weakly_canonical(filename, error);
      for (const std::string &link : chain)
        if (fs::weakly_canonical(link, error) == here)
          {
            std::string words;
            for (unsigned int k = 0; k + 1 < shown_chain.size(); ++k)
              words += "'" + shown_chain[k] + "' includes ";
            throw InputError("Parameter file '" + shown_chain.front() +
                             "': includes run in a circle: " + words + "'" +
                             shown_chain.back() + "'.");
          }
      std::ifstream in(filename);
      chain.push_back(filename);
      std::string line;
      for (unsigned int number = 1; std::getline(in, line); ++number)
        {
          const Origin      origin{shown_chain.back(), number};
          const std::string text = statement(line);
          const bool        include =
            (text.rfind("include", 0) == 0 || text.rfind("INCLUDE", 0) == 0) &&
            text.size() > 7 &&
            std::isspace(static_cast<unsigned char>(text[7]));
          if (include)
            {
              const std::string name = Utilities::trim(text.substr(7));
              const fs::path    path = relative_to(name, filename);
              std::ifstream     test(path);
              if (!test || fs::is_directory(path))
                {
                  std::string message = "Parameter file " + origin.text() +
                                        ": cannot read the included file '" +
                                        name + "' (looked for " +
                                        path.string() +
                                        ": an include names "
                                        "a file relative to the directory of "
                                        "the file that holds it).";
                  if (!fs::path(name).is_absolute() && fs::exists(name))
                    message += " A file '" + name +
                               "' exists relative to "
                               "the working directory: write its path "
                               "relative to the parameter file, or absolute.";
                  throw InputError(message);
                }
              std::vector<std::string> shown = shown_chain;
              shown.push_back(name);
              // (The included file's subsections nest in the current one.)
              expand(
                path.string(), file_entries, sections, chain, shown, expanded);
              // The include line itself stays, as a comment.
              expanded.lines.push_back("# " + text);
              expanded.origins.push_back(origin);
              continue;
            }
          std::string rewritten = line;
          if (text.rfind("subsection ", 0) == 0)
            sections.push_back(Utilities::trim(text.substr(11)));
          else if (text == "end" && !sections.empty())
            sections.pop_back();
          else if (text.rfind("set ", 0) == 0 &&
                   text.find('=') != std::string::npos)
            {
              const std::string::size_type equal = text.find('=');
              std::string                  key;
              for (const std::string &section : sections)
                key += section + "/";
              key += Utilities::trim(text.substr(4, equal - 4));
              const std::string value = Utilities::trim(text.substr(equal + 1));
              if (file_entries.count(key) && !value.empty())
                rewritten = line.substr(0, line.find("set ")) + "set " +
                            Utilities::trim(text.substr(4, equal - 4)) + " = " +
                            relative_to(value, filename).string();
            }
          expanded.lines.push_back(rewritten);
          expanded.origins.push_back(origin);
        }
      chain.pop_back();
    }

    /**
     * ParameterHandler keeps the last of two `set` lines of one entry
     * without a word; a repeated entry in one file is most often an edit
     * that missed the earlier line, so say which value wins (rank 0, on
     * stderr). An entry that overrides one of an included file is what an
     * include is for: no warning.
     */
    void
    warn_about_repeated_entries(const ExpandedFile &expanded)
    {
      if (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) != 0)
        return;
      std::vector<std::string>                                    path;
      std::map<std::pair<std::string, std::string>, unsigned int> first;
      for (unsigned int i = 0; i < expanded.lines.size(); ++i)
        {
          const std::string line = statement(expanded.lines[i]);
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
              const Origin &here = expanded.origins[i];
              const auto [it, inserted] =
                first.emplace(std::make_pair(here.file, key), here.line);
              if (!inserted)
                {
                  std::cerr << "Warning: " << here.file << ": " << key
                            << " is set on lines " << it->second << " and "
                            << here.line << "; the value on line " << here.line
                            << " is used." << std::endl;
                  it->second = here.line;
                }
            }
        }
    }

    /// @p message (of ParameterHandler, about the expanded text) with its
    /// "Line <n> of file <f>" put back where the line comes from.
    std::string
    locate(const std::string &message, const ExpandedFile &expanded)
    {
      static const std::regex where("Line <([0-9]+)> of file <[^>]*>");
      std::smatch             match;
      if (!std::regex_search(message, match, where))
        return message;
      const unsigned long n = std::stoul(match[1].str());
      if (n == 0 || n > expanded.origins.size())
        return message;
      const Origin &origin = expanded.origins[n - 1];
      return match.prefix().str() + "Line <" + std::to_string(origin.line) +
             "> of file <" + origin.file + ">" + match.suffix().str();
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
                "Cannot open the parameter file '" + filename +
                  "' (looked for " +
                  fs::absolute(filename).lexically_normal().string() + ").");
    const std::string text((std::istreambuf_iterator<char>(in)),
                           std::istreambuf_iterator<char>());
    check_input(text.find("set ") != std::string::npos,
                "The parameter file '" + filename +
                  "' sets no entry (it is empty or holds only comments).");
    ExpandedFile             expanded;
    std::vector<std::string> sections, chain;
    expand(
      filename, file_name_entries(prm), sections, chain, {filename}, expanded);
    warn_about_repeated_entries(expanded);
    std::string all;
    for (const std::string &line : expanded.lines)
      all += line + '\n';
    try
      {
        std::istringstream stream(all);
        prm.parse_input(stream, filename);
      }
    catch (const std::exception &e)
      {
        throw InputError("Parameter file '" + filename +
                         "': " + locate(message_of(e), expanded));
      }
  }



  void
  set_from_command_line(ParameterHandler &prm, const std::string &assignment)
  {
    const std::string            where = "-s '" + assignment + "'";
    const std::string::size_type equal = assignment.find('=');
    check_input(equal != std::string::npos,
                where + ": not of the form 'Subsection/Entry=value'.");
    const std::string path  = Utilities::trim(assignment.substr(0, equal));
    std::string       value = Utilities::trim(assignment.substr(equal + 1));
    std::vector<std::string> parts = Utilities::split_string_list(path, '/');
    check_input(!path.empty() && !parts.empty() &&
                  std::find(parts.begin(), parts.end(), "") == parts.end(),
                where + ": names no entry.");
    // A file named on the command line is relative to the working
    // directory.
    if (file_name_entries(prm).count(path) && !value.empty())
      value = fs::absolute(value).lexically_normal().string();
    unsigned int depth = 0;
    try
      {
        for (; depth + 1 < parts.size(); ++depth)
          {
            // (enter_subsection() would declare a subsection that does not
            // exist.)
            check_input(prm.subsection_path_exists({parts[depth]}),
                        where + ": there is no subsection '" + parts[depth] +
                          "'" +
                          (depth > 0 ? " in '" + parts[depth - 1] + "'" : "") +
                          " (xcrack --print-parameters lists them).");
            prm.enter_subsection(parts[depth]);
          }
        prm.set(parts.back(), value);
      }
    catch (const InputError &)
      {
        for (; depth > 0; --depth)
          prm.leave_subsection();
        throw;
      }
    catch (const std::exception &e)
      {
        for (; depth > 0; --depth)
          prm.leave_subsection();
        throw InputError(where + ": " + message_of(e));
      }
    for (; depth > 0; --depth)
      prm.leave_subsection();
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
