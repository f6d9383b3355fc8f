#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>
#include <gelmpm/io/output_directory.h>
#include <gelmpm/simulator/peer_input.h>
#include <gelmpm/simulator/scene_structure.h>
#include <gelmpm/simulator/simulator.h>

#include <filesystem>
#include <sstream>

namespace GelMPM
{
  PeerInput::PeerInput(const int                                              argc,
                       const char *const                                     *argv,
                       const std::string                                     &tool,
                       const std::function<void(dealii::ParameterHandler &)> &declare_peer)
    : tool(tool)
  {
    // gelmpm's own command line, without the peer's one switch.
    std::vector<const char *> arguments;
    for (int i = 0; i < argc; ++i)
      if (std::string(argv[i]) == "--quiet")
        quiet = true;
      else
        arguments.push_back(argv[i]);
    for (const auto *argument : arguments)
      for (const char *option : {"--check", "--resume", "--print-parameters"})
        require(std::string(argument) != option,
                "",
                "'" + std::string(option) + "' is an option of gelmpm, not of " + tool,
                "see '" + tool + " --help'");
    const auto cl = CommandLine::parse(arguments.size(), arguments.data());
    help          = cl.help;
    scene_file    = cl.scene_file;

    prm.enter_subsection("FE peer");
    declare_peer(prm);
    prm.leave_subsection();
    if (help)
      return;
    const auto structure = SceneStructure::read(cl.scene_file, cl.overrides);
    require(structure.dimension == 2,
            "Dimension",
            "is " + std::to_string(structure.dimension) + ", but the body-fitted peer runs in 2D",
            "give the 2D scene the peer is compared with");
    Simulator<2>::declare_parameters(prm, structure);
    read_scene_file(prm, cl.scene_file, cl.overrides);
    material.parse_parameters(prm);
    regions.parse_parameters(prm, structure.material_regions, material);
    time_stepping.parse_parameters(prm);
    newton.parse_parameters(prm);
    time_stepping.check_resolvable(newton.tolerance, NewtonSettings::smallest_tolerance);
    linear_solver.parse_parameters(prm);
    stability.parse_parameters(prm);
  }


  std::string
  PeerInput::usage(const std::string &description) const
  {
    std::ostringstream text;
    text << "Usage: " << tool << " [--set \"Section/Entry=value\"]... [--quiet] scene.prm\n\n"
         << description << "\n\n"
         << "The gel, 'Time stepping', 'Newton', 'Linear solver' and 'Stability' are the scene's "
            "(gelmpm --print-parameters documents them);\nthe peer's own entries are set with "
            "--set \"FE peer/Entry=value\":\n\n";
    // With --help only the peer's section is declared: its entries with their documentation.
    prm.print_parameters(text, dealii::ParameterHandler::Text);
    text << "\n  --quiet   no line per step\n  --help    this text\n";
    return text.str();
  }


  void
  PeerInput::declare_degree(dealii::ParameterHandler &prm)
  {
    prm.declare_entry("Degree",
                      "2",
                      dealii::Patterns::Integer(2),
                      "Displacement degree k (mu: k - 1, Taylor-Hood), at most " +
                        std::to_string(largest_degree) + ".");
  }


  unsigned int
  PeerInput::degree(const dealii::ParameterHandler &prm)
  {
    const long k = prm.get_integer("Degree");
    require(k <= static_cast<long>(largest_degree),
            "FE peer/Degree",
            "is " + std::to_string(k) + ", above " + std::to_string(largest_degree) +
              ": a cell's matrix and quadrature tables grow as the degree to the sixth power "
              "(one step of the 2 x 20 cell layer took 3 s at degree 6, 23 s at 10; 40 ran out "
              "of memory)",
            "give a degree from 2 to " + std::to_string(largest_degree) +
              " and refine 'FE peer/Cells' instead");
    return k;
  }


  void
  PeerInput::declare_output_directory(dealii::ParameterHandler &prm,
                                      const std::string        &default_directory,
                                      const std::string        &contents)
  {
    prm.declare_entry("Output directory",
                      default_directory,
                      dealii::Patterns::Anything(),
                      "The directory of " + contents + ".");
  }


  void
  PeerInput::require_one_gel() const
  {
    if (regions.size() <= 1)
      return;
    std::string names;
    for (unsigned int r = 1; r < regions.size(); ++r)
      names += (r == 1 ? "" : ", ") + regions.name(r);
    throw InputError("Material/Regions",
                     "names the region(s) " + names + ", but " + tool +
                       " builds its body of one gel, the section's own, and would drop them",
                     "run the peer on the scene without its regions (--set \"Material/Regions=\"), "
                     "or compare a body of two gels with gelmpm-fem-bilayer");
  }


  std::unique_ptr<DirectoryLock>
  PeerInput::claim_output_directory(const std::string &directory) const
  {
    const std::string entry = "FE peer/Output directory";
    check_output_directory(directory, entry, scene_file, false);
    namespace fs = std::filesystem;
    std::error_code error;
    for (const char *name : {"parameters.prm", "original.prm", "particles.pvd", "checkpoint.bin"})
      require(!fs::exists(fs::path(directory) / name, error),
              entry,
              "is '" + directory + "', which holds the results of a gelmpm run ('" + name +
                "'): the peer's statistics.csv would replace that run's",
              "give the peer a directory of its own, e.g. --set \"" + entry + "=fem\"");
    fs::create_directories(directory, error);
    require(!error,
            entry,
            "'" + directory + "' cannot be created (" + error.message() + ")",
            "choose a directory you can write to");
    return std::make_unique<DirectoryLock>(directory, entry);
  }


  dealii::ParameterHandler &
  PeerInput::peer_section()
  {
    prm.enter_subsection("FE peer");
    return prm;
  }


  void
  PeerInput::leave_peer_section()
  {
    prm.leave_subsection();
  }
} // namespace GelMPM
