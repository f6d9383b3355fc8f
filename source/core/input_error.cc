#include <gelmpm/core/input_error.h>

namespace GelMPM
{
  namespace
  {
    const std::string ellipsis = "\u2026";

    /**
     * @p text with every word longer than 80 characters cut to 80 and the whole cut to 600: a
     * message echoes the user's value, which may be megabytes long.
     */
    std::string
    shorten(const std::string &text)
    {
      constexpr std::size_t longest_word = 80, longest_text = 600;
      std::string           result;
      std::size_t           word = 0;
      for (char c : text)
        {
          if (c == '\n' || c == '\r' || c == '\t')
            c = ' '; // the message is one line
          word = (c == ' ') ? 0 : word + 1;
          if (word <= longest_word)
            result += c;
          else if (word == longest_word + 1)
            result += ellipsis;
        }
      if (result.size() > longest_text)
        {
          std::size_t end = longest_text;
          while (end > 0 && (static_cast<unsigned char>(result[end]) & 0xC0) == 0x80)
            --end; // not inside a UTF-8 character
          result = result.substr(0, end) + ellipsis;
        }
      return result;
    }

    std::string
    compose(const std::string &entry, const std::string &problem_text, const std::string &fix_text)
    {
      const std::string problem = shorten(problem_text), fix = shorten(fix_text);
      std::string       message = entry.empty() ? problem : ("'" + shorten(entry) + "' " + problem);
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
