#include <gelmpm/core/input_error.h>

namespace GelMPM
{
  namespace
  {
    std::string
    compose(const std::string &entry, const std::string &problem, const std::string &fix)
    {
      std::string message = entry.empty() ? problem : ("'" + entry + "' " + problem);
      if (!fix.empty())
        message += ". Fix: " + fix;
      return message;
    }
  } // namespace

  InputError::InputError(const std::string &entry,
                         const std::string &problem,
                         const std::string &fix)
    : std::runtime_error(compose(entry, problem, fix))
    , entry_(entry)
    , problem_(problem)
    , fix_(fix)
  {}

  const std::string &
  InputError::entry() const
  {
    return entry_;
  }

  const std::string &
  InputError::problem() const
  {
    return problem_;
  }

  const std::string &
  InputError::fix() const
  {
    return fix_;
  }
} // namespace GelMPM
