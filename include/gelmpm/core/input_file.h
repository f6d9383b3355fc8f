#ifndef gelmpm_core_input_file_h
#define gelmpm_core_input_file_h

#include <cstdint>
#include <string>

namespace GelMPM
{
  /** The largest scene file (or file it includes) read: scenes are a few kilobytes. */
  constexpr std::uintmax_t largest_scene_file_bytes = std::uintmax_t(32) << 20;

  /** The largest mesh file read ('Geometry/Mesh file'). */
  constexpr std::uintmax_t largest_mesh_file_bytes = std::uintmax_t(1) << 30;

  /**
   * Throw InputError naming @p entry unless the file @p path, if it exists, can be read to its end:
   * a regular file of at most @p largest_bytes. A device such as /dev/zero, a pipe or a socket has
   * no size that bounds the read (reading it ran until the memory was gone), and a file far larger
   * than any @p what ("a scene file") is the wrong file. @p fix says what to give instead. A path
   * that does not exist passes: the caller reports it in its own words.
   */
  void
  require_bounded_file(const std::string   &path,
                       const std::string   &entry,
                       const std::string   &what,
                       const std::uintmax_t largest_bytes,
                       const std::string   &fix);
} // namespace GelMPM

#endif
