/**
 * xcrack: fatigue crack propagation with the extended finite element method.
 *
 *   xcrack [-s ENTRY=VALUE]... FILE.prm   run the scene of FILE.prm
 *   mpirun -np N xcrack FILE.prm          the same on N ranks
 *   xcrack --check [-s ...] FILE.prm      read the scene, run every input
 *                                         check, and stop
 *   xcrack --resume DIR                   continue the propagation run whose
 *                                         output directory DIR holds a
 *                                         checkpoint
 *   xcrack --print-parameters [json]      every parameter with default and
 *                                         documentation
 *   xcrack --version
 *
 * Exit codes: 0 success, 1 bad input (message names the culprit), 2 failure
 * during the computation (a file that cannot be written, the solver), 3 a
 * numerical failure (a value that is not finite, a singular system).
 */

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <xcrack/command_line.h>
#include <xcrack/input_error.h>
#include <xcrack/parameters.h>
#include <xcrack/run.h>

#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace
{
  void
  print_usage(std::ostream &out)
  {
    out
      << "Usage: xcrack [-s ENTRY=VALUE]... FILE.prm\n"
      << "       mpirun -np N xcrack FILE.prm\n"
      << "       xcrack --check [-s ENTRY=VALUE]... FILE.prm\n"
      << "       xcrack --resume OUTPUT_DIRECTORY\n"
      << "       xcrack --print-parameters [prm|json]\n"
      << "       xcrack --version\n"
      << "\n"
      << "  -s, --set ENTRY=VALUE  set an entry after reading FILE.prm, its\n"
      << "                         subsections separated by '/', e.g.\n"
      << "                         -s \"Propagation/Maximum advance=0.002\"\n"
      << "                         (recorded in run.json)\n"
      << "  --check                read the scene and run every input check\n"
      << "                         (those of the first solve excepted),\n"
      << "                         then stop: no result is written\n"
      << "  --resume DIR           continue the run checkpointed in DIR\n"
      << "  --print-parameters     every entry, its default and its meaning,\n"
      << "                         as a parameter file or (json) for tools\n"
      << "  --version              the commit xcrack was built from\n";
  }

  /// What the command line asks for.
  struct Arguments
  {
    enum class Action
    {
      run,
      check,
      resume,
      print_parameters,
      version,
      help
    } action = Action::run;
    /// The parameter file, or the directory to resume.
    std::string              target;
    std::vector<std::string> overrides;
  };

  /// The arguments, or an error message.
  std::pair<std::optional<Arguments>, std::string>
  parse_arguments(const int argc, char *argv[])
  {
    using Action = Arguments::Action;
    Arguments                arguments;
    std::vector<std::string> positional;
    bool                     action_given = false;
    const auto               set_action   = [&](const Action action) {
      const bool twice = action_given;
      action_given     = true;
      arguments.action = action;
      return !twice;
    };
    for (int i = 1; i < argc; ++i)
      {
        const std::string argument = argv[i];
        if (argument == "-s" || argument == "--set")
          {
            if (i + 1 == argc)
              return {std::nullopt, argument + " takes ENTRY=VALUE."};
            arguments.overrides.emplace_back(argv[++i]);
          }
        else if (argument.rfind("--set=", 0) == 0)
          arguments.overrides.push_back(argument.substr(6));
        else if (argument == "--check" || argument == "--resume" ||
                 argument == "--print-parameters" || argument == "--version" ||
                 argument == "--help" || argument == "-h")
          {
            const Action action =
              (argument == "--check"            ? Action::check :
               argument == "--resume"           ? Action::resume :
               argument == "--print-parameters" ? Action::print_parameters :
               argument == "--version"          ? Action::version :
                                                  Action::help);
            if (!set_action(action))
              return {std::nullopt,
                      "give one of --check, --resume, --print-parameters, "
                      "--version, --help."};
          }
        else if (argument.size() > 1 && argument[0] == '-')
          return {std::nullopt, "unknown option '" + argument + "'."};
        else
          positional.push_back(argument);
      }
    switch (arguments.action)
      {
        case Action::run:
        case Action::check:
          if (positional.size() != 1)
            return {std::nullopt, "give one parameter file."};
          break;
        case Action::resume:
          if (positional.size() != 1)
            return {std::nullopt,
                    "--resume takes one argument, the output directory of "
                    "the run to continue."};
          if (!arguments.overrides.empty())
            return {std::nullopt,
                    "-s does not apply to --resume: a resumed run keeps the "
                    "parameters of its checkpoint (to change them, start "
                    "anew)."};
          break;
        case Action::print_parameters:
          if (positional.size() > 1 || !arguments.overrides.empty() ||
              (positional.size() == 1 && positional[0] != "prm" &&
               positional[0] != "json"))
            return {std::nullopt,
                    "--print-parameters takes prm (the default) or json."};
          break;
        default:
          if (!positional.empty() || !arguments.overrides.empty())
            return {std::nullopt, "this option takes no other argument."};
      }
    if (!positional.empty())
      arguments.target = positional.front();
    return {arguments, ""};
  }
} // namespace

int
main(int argc, char *argv[])
{
  using namespace dealii;
  Utilities::MPI::MPI_InitFinalize mpi_initialization(argc, argv, 1);
  const bool root = (Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0);

  const auto [parsed, usage_error] = parse_arguments(argc, argv);
  if (!parsed)
    {
      if (root)
        {
          std::cerr << "xcrack: " << usage_error << std::endl;
          print_usage(std::cerr);
        }
      return 1;
    }
  const Arguments &arguments = *parsed;
  using Action               = Arguments::Action;

  try
    {
      ParameterHandler prm;
      xcrack::declare_all_parameters(prm);

      switch (arguments.action)
        {
          case Action::print_parameters:
            if (root)
              xcrack::print_parameters(prm,
                                       std::cout,
                                       arguments.target == "json" ?
                                         ParameterHandler::JSON :
                                         ParameterHandler::PRM);
            return 0;
          case Action::version:
            if (root)
              std::cout << "xcrack " << xcrack::version() << " (deal.II "
                        << DEAL_II_PACKAGE_VERSION << ")" << std::endl;
            return 0;
          case Action::help:
            if (root)
              print_usage(std::cout);
            return 0;
          case Action::resume:
            {
              // The run's own parameters, kept with the checkpoint; its
              // results stay where they are.
              const std::string &directory = arguments.target;
              xcrack::read_parameter_file(prm,
                                          xcrack::checkpoint_of(directory) +
                                            "/parameters.prm");
              prm.set("Output directory", directory);
              xcrack::RunOptions options;
              options.resume_directory = directory;
              xcrack::run(prm, options);
              break;
            }
          case Action::run:
          case Action::check:
            {
              xcrack::read_parameter_file(prm, arguments.target);
              for (const std::string &assignment : arguments.overrides)
                xcrack::set_from_command_line(prm, assignment);
              xcrack::RunOptions options;
              options.overrides  = arguments.overrides;
              options.check_only = (arguments.action == Action::check);
              xcrack::run(prm, options);
              if (options.check_only && root)
                std::cout << "xcrack: " << arguments.target
                          << ": every input check passed (the crowns and "
                             "the lip pressure are checked where they are "
                             "used, in the first solve)."
                          << std::endl;
              break;
            }
        }
    }
  catch (const xcrack::InputError &e)
    {
      if (root)
        std::cerr << "xcrack: input error: " << e.what() << std::endl;
      return 1;
    }
  catch (const xcrack::NumericalError &e)
    {
      if (root)
        std::cerr << "xcrack: numerical failure: " << e.what() << std::endl;
      return 3;
    }
  catch (const std::bad_alloc &)
    {
      // Out of memory before the first solve (the Simulator reports those
      // with their DoF count): the mesh or the input checks did not fit.
      std::cerr << "xcrack: error: out of memory while building the mesh "
                   "and checking the input: use a coarser mesh (Mesh/Initial "
                   "global refinement) or more ranks."
                << std::endl;
      return 2;
    }
  catch (const std::exception &e)
    {
      std::cerr << "xcrack: error: " << e.what() << std::endl;
      return 2;
    }
  return 0;
}
