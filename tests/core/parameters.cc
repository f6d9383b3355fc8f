// The parameter helpers of core: a --set override is split into its sections, entry and value
// (and text without '=' or without an entry is an InputError); the command line is parsed into
// scene file, overrides and flags (an unknown option is an InputError); a scene file is read
// strictly, so that an unknown entry or a value outside its pattern is one InputError naming it;
// a list entry of the wrong length or with a non-number names its entry; the listing of
// --print-parameters gives every entry's pattern; entry_value() gives the text that reads back to
// the same double.
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/parameters.h>

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace GelMPM;

namespace
{
  bool ok = true;

  void
  check(const bool condition, const std::string &what)
  {
    std::cout << "  " << what << ": " << (condition ? "yes" : "no  FAIL") << std::endl;
    ok &= condition;
  }

  /** The message of the InputError that @p f throws, or "" if it throws none. */
  template <typename F>
  std::string
  error_of(const F &f)
  {
    try
      {
        f();
      }
    catch (const InputError &e)
      {
        return e.what();
      }
    return "";
  }

  void
  declare(dealii::ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    prm.declare_entry("Diffusivity", "1", dealii::Patterns::Double(0.));
    prm.declare_entry("Corner", "0, 0", dealii::Patterns::Anything());
    prm.leave_subsection();
  }

  /** Read @p text as a scene file through read_scene_file(). */
  void
  read(dealii::ParameterHandler             &prm,
       const std::string                    &text,
       const std::vector<ParameterOverride> &overrides = {})
  {
    const std::string name = "parameters_test.prm";
    std::ofstream(name) << text;
    try
      {
        read_scene_file(prm, name, overrides);
      }
    catch (...)
      {
        std::remove(name.c_str());
        throw;
      }
    std::remove(name.c_str());
  }
} // namespace

int
main()
{
  std::cout << "ParameterOverride::parse" << std::endl;
  const auto o = ParameterOverride::parse("Boundary conditions/top/Selector=ny > 0.5");
  check(o.sections == std::vector<std::string>{"Boundary conditions", "top"} &&
          o.entry == "Selector" && o.value == "ny > 0.5",
        "sections, entry and value");
  check(o.path() == "Boundary conditions/top/Selector", "path()");
  const std::string no_equal = error_of([] {
    ParameterOverride::parse("Material/Diffusivity");
  });
  std::cout << "  " << no_equal << std::endl;
  check(!no_equal.empty(), "text without '=' is an InputError");
  check(!error_of([] {
           ParameterOverride::parse(" = 1");
         }).empty(),
        "an override without an entry name is an InputError");

  std::cout << "CommandLine::parse" << std::endl;
  {
    const char *argv[] = {"gelmpm", "--check", "--set", "Material/Diffusivity=2", "scene.prm"};
    const auto  line   = CommandLine::parse(5, argv);
    check(line.check_only && !line.help && line.scene_file == "scene.prm" &&
            line.overrides.size() == 1 && line.overrides[0].value == "2",
          "--check, --set and the scene file");
    const char *bad[] = {"gelmpm", "--frobnicate", "scene.prm"};
    check(!error_of([&] {
             CommandLine::parse(3, bad);
           }).empty(),
          "an unknown option is an InputError");
  }

  std::cout << "read_scene_file" << std::endl;
  {
    dealii::ParameterHandler prm;
    declare(prm);
    read(prm,
         "subsection Material\n  set Diffusivity = 3\nend\n",
         {ParameterOverride::parse("Material/Corner=1, 2")});
    prm.enter_subsection("Material");
    check(prm.get_double("Diffusivity") == 3., "the file's value is read");
    check(prm.get("Corner") == "1, 2", "an override wins over the file");
    const auto corner = get_double_list(prm, "Corner", "Material/Corner", 2);
    check(corner == std::vector<double>{1., 2.}, "get_double_list() reads the list");
    const std::string count = error_of([&] {
      get_double_list(prm, "Corner", "Material/Corner", 3);
    });
    std::cout << "  " << count << std::endl;
    check(count.find("'Material/Corner'") == 0, "a wrong count names the entry");
    prm.set("Corner", "1, a");
    const std::string nan = error_of([&] {
      get_double_list(prm, "Corner", "Material/Corner", 2);
    });
    std::cout << "  " << nan << std::endl;
    check(nan.find("'Material/Corner'") == 0, "a non-number names the entry");
    prm.leave_subsection();
  }
  {
    dealii::ParameterHandler prm;
    declare(prm);
    const std::string unknown = error_of([&] {
      read(prm, "subsection Material\n  set Diffusivty = 3\nend\n");
    });
    std::cout << "  " << unknown << std::endl;
    check(unknown.find("Diffusivty") != std::string::npos &&
            unknown.find("Diffusivity") != std::string::npos,
          "a misspelt entry is named, with the nearest declared name");
    const std::string pattern = error_of([&] {
      read(prm, "subsection Material\n  set Diffusivity = -1\nend\n");
    });
    std::cout << "  " << pattern << std::endl;
    check(pattern.find("Diffusivity") != std::string::npos,
          "a value outside its pattern names the entry");
  }

  std::cout << "print_parameters_with_patterns" << std::endl;
  {
    dealii::ParameterHandler prm;
    declare(prm);
    std::ostringstream out;
    print_parameters_with_patterns(prm, out);
    const std::string text = out.str();
    check(text.find("  # Pattern: [Double 0...MAX_DOUBLE (inclusive)]\n  set Diffusivity = 1") !=
            std::string::npos,
          "the listing gives an entry's pattern right above it");
    check(text.find("# Pattern: [Anything]\n  set Corner") != std::string::npos,
          "and that of every other entry");
  }

  std::cout << "entry_value" << std::endl;
  for (const double x : {0.1, 1. / 3., 6.02214076e23, -2.5e-300})
    check(dealii::Utilities::string_to_double(entry_value(x)) == x,
          "'" + entry_value(x) + "' reads back exactly");

  std::cout << (ok ? "OK" : "FAILED") << std::endl;
  return ok ? 0 : 1;
}
