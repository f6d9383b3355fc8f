// InputError and require(), the one way input is rejected: the message is one line
// "'<entry>' <problem>. Fix: <fix>", without the entry when it is empty and without the fix when
// there is none; a value the user typed is echoed shortened (a word to 80 characters, the whole
// to 600, line breaks to spaces) so that a megabyte value gives a readable message, while the
// accessors keep the original text; require() throws exactly when its condition fails.
#include <gelmpm/core/input_error.h>

#include <iostream>
#include <string>

using GelMPM::InputError;

namespace
{
  bool ok = true;

  void
  check(const bool condition, const std::string &what)
  {
    std::cout << "  " << what << ": " << (condition ? "yes" : "no  FAIL") << std::endl;
    ok &= condition;
  }
} // namespace

int
main()
{
  std::cout << "Message format" << std::endl;
  const InputError full("Material/Diffusivity", "must be positive, but is -1", "give D > 0");
  std::cout << "  " << full.what() << std::endl;
  check(std::string(full.what()) ==
          "'Material/Diffusivity' must be positive, but is -1. Fix: give D > 0",
        "entry, problem and fix");
  const InputError no_entry("", "the scene file is empty", "give a scene");
  std::cout << "  " << no_entry.what() << std::endl;
  check(std::string(no_entry.what()) == "the scene file is empty. Fix: give a scene",
        "no quotes without an entry");
  const InputError no_fix("Output/Directory", "is empty");
  std::cout << "  " << no_fix.what() << std::endl;
  check(std::string(no_fix.what()) == "'Output/Directory' is empty", "no 'Fix:' without a fix");
  check(full.entry() == "Material/Diffusivity" && full.problem() == "must be positive, but is -1" &&
          full.fix() == "give D > 0",
        "accessors return the parts");

  std::cout << "Long values are shortened" << std::endl;
  const std::string long_word(100000, 'x');
  const InputError  long_value("Geometry/Boxes", "has the item '" + long_word + "'", "fix it");
  const std::string message = long_value.what();
  std::cout << "  message length " << message.size() << " bytes" << std::endl;
  check(message.size() < 700, "the message stays short");
  check(message.find(std::string(81, 'x')) == std::string::npos, "no word beyond 80 characters");
  check(message.find("\u2026") != std::string::npos, "the cut is marked with an ellipsis");
  check(long_value.problem().size() > 100000, "problem() keeps the whole text");
  const InputError lines("Selector", "is 'a\nb\tc'");
  check(std::string(lines.what()).find_first_of("\n\t") == std::string::npos,
        "line breaks and tabs become spaces");

  std::cout << "require()" << std::endl;
  bool thrown = false;
  try
    {
      GelMPM::require(true, "A/B", "never");
    }
  catch (const InputError &)
    {
      thrown = true;
    }
  check(!thrown, "a condition that holds throws nothing");
  try
    {
      GelMPM::require(false, "A/B", "is wrong", "set it right");
    }
  catch (const InputError &e)
    {
      thrown = true;
      std::cout << "  " << e.what() << std::endl;
      check(e.entry() == "A/B" && e.fix() == "set it right", "the entry and fix are passed on");
    }
  check(thrown, "a failing condition throws InputError");

  std::cout << (ok ? "OK" : "FAILED") << std::endl;
  return ok ? 0 : 1;
}
