// Runs the bad-input cases of tests/input_errors (CMakeLists.txt there says what a case is and
// when it passes) as gelmpm runs them, each in a forked copy of this one program: the copy calls
// GelMPM::run_command_line(), which is all that gelmpm's main() does, in an empty scratch
// directory with stdout and stderr in files. Starting a program linked with deal.II costs about
// 0.4 s of symbol resolution, more than most bad input takes to be found; forked copies of a
// program that has resolved them once do not pay it again.
//
//   input_error_runner CASE.prm...
//
// Prints one line per case (PASS, or FAIL with the reasons and the case's stderr) and exits with
// status 1 if any case failed.
#include <gelmpm/simulator/command_line_main.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

namespace
{
  namespace fs = std::filesystem;

  /** The header lines of a case file (CMakeLists.txt in this directory). */
  struct CaseHeader
  {
    std::string expect;
    std::string args;
    std::string scene;
    std::string setup;
  };


  /** The text after @p prefix on the lines of @p lines that start with it, joined by newlines. */
  std::string
  entries(const std::vector<std::string> &lines, const std::string &prefix)
  {
    std::string text;
    for (const auto &line : lines)
      if (line.compare(0, prefix.size(), prefix) == 0)
        text += (text.empty() ? "" : "\n") + line.substr(prefix.size());
    return text;
  }


  /** The lines of @p file. */
  std::vector<std::string>
  lines_of(const fs::path &file)
  {
    std::ifstream            in(file, std::ios::binary);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
      lines.push_back(line);
    return lines;
  }


  CaseHeader
  read_header(const std::string &case_file)
  {
    const auto lines = lines_of(case_file);
    CaseHeader header;
    if (!lines.empty())
      {
        std::string first = lines.front();
        if (first.compare(0, 3, "\xEF\xBB\xBF") == 0)
          first.erase(0, 3);
        if (first.compare(0, 10, "# expect: ") == 0)
          header.expect = first.substr(10);
      }
    header.args  = entries(lines, "# args: ");
    header.scene = entries(lines, "# scene: ");
    header.setup = entries(lines, "# setup: ");
    if (header.scene.empty())
      header.scene = case_file;
    return header;
  }


  /** Every path below @p directory, relative to it, but @p ignored. */
  std::set<std::string>
  listing(const fs::path &directory, const std::set<std::string> &ignored = {})
  {
    std::set<std::string> paths;
    std::error_code       error;
    for (auto it = fs::recursive_directory_iterator(directory, error);
         !error && it != fs::recursive_directory_iterator();
         it.increment(error))
      {
        const std::string path = fs::relative(it->path(), directory).string();
        if (!ignored.count(path))
          paths.insert(path);
      }
    return paths;
  }


  /** Wait for @p child; its exit status, or 128 + the signal that ended it. */
  int
  wait_for(const pid_t child)
  {
    int status = 0;
    while (waitpid(child, &status, 0) < 0)
      if (errno != EINTR)
        return -1;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }


  /**
   * In @p work: the case's setup command run by bash with CASE naming the case file, as the
   * shell tests did, then its arguments expanded by bash into @p argv_file (NUL-separated).
   */
  bool
  prepare(const fs::path    &work,
          const std::string &case_file,
          const CaseHeader  &header,
          const fs::path    &argv_file)
  {
    const pid_t child = fork();
    if (child == 0)
      {
        if (chdir(work.c_str()) != 0)
          _exit(127);
        setenv("CASE", case_file.c_str(), 1);
        setenv("GELMPM_SETUP", header.setup.c_str(), 1);
        setenv("GELMPM_ARGS", header.args.c_str(), 1);
        setenv("GELMPM_ARGV_FILE", argv_file.c_str(), 1);
        execl("/bin/bash",
              "bash",
              "-c",
              "eval \"$GELMPM_SETUP\"; eval \"set -- $GELMPM_ARGS\"; "
              "printf '%s\\0' \"$@\" > \"$GELMPM_ARGV_FILE\"",
              static_cast<char *>(nullptr));
        _exit(127);
      }
    return child > 0 && wait_for(child) == 0;
  }


  std::vector<std::string>
  read_arguments(const fs::path &argv_file)
  {
    std::ifstream            in(argv_file, std::ios::binary);
    std::vector<std::string> arguments;
    for (std::string argument; std::getline(in, argument, '\0');)
      arguments.push_back(argument);
    return arguments;
  }


  /** gelmpm's command line run in a forked copy, in @p work; its exit status. */
  int
  run_gelmpm(const fs::path &work, const std::vector<std::string> &arguments)
  {
    std::cout.flush();
    std::cerr.flush();
    std::fflush(nullptr);
    const pid_t child = fork();
    if (child == 0)
      {
        if (chdir(work.c_str()) != 0)
          _exit(127);
        const int out = open("stdout", O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = open("stderr", O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (out < 0 || err < 0 || dup2(out, 1) < 0 || dup2(err, 2) < 0)
          _exit(127);
        close(out);
        close(err);
        // A case that hangs is ended (and fails) rather than holding the whole suite.
        alarm(300);
        std::vector<std::string> copies = arguments;
        std::vector<char *>      argv;
        for (auto &argument : copies)
          argv.push_back(argument.data());
        argv.push_back(nullptr);
        const int status = GelMPM::run_command_line(static_cast<int>(argv.size()) - 1, argv.data());
        // As main() returning: static objects are destroyed and the streams flushed.
        std::exit(status);
      }
    return child > 0 ? wait_for(child) : -1;
  }


  /**
   * What is wrong with a refused run: its exit @p status, its @p stderr_lines against the
   * @p expect ed text, and the files it @p wrote. Empty if nothing.
   */
  std::vector<std::string>
  refusal_failures(const int                       status,
                   const std::vector<std::string> &stderr_lines,
                   const std::string              &expect,
                   const std::vector<std::string> &wrote)
  {
    std::vector<std::string> failures;
    if (status != 2)
      failures.push_back("exit status " + std::to_string(status) + ", expected 2");
    bool        found   = false;
    std::size_t longest = 0, non_empty = 0;
    for (const auto &line : stderr_lines)
      {
        found |= line.find(expect) != std::string::npos;
        longest = std::max(longest, line.size());
        non_empty += line.empty() ? 0 : 1;
      }
    if (!found)
      failures.push_back("stderr lacks '" + expect + "'");
    if (non_empty != 1)
      failures.push_back("expected exactly one error line, found " + std::to_string(non_empty));
    if (longest > 1000)
      failures.push_back("the error line is longer than 1000 characters");
    if (!wrote.empty())
      failures.push_back("output was written: " + wrote.front() +
                         (wrote.size() > 1 ? " and more" : ""));
    return failures;
  }


  /** Run one case; print its result; whether it passed. */
  bool
  run_case(const std::string &case_file, const fs::path &scratch)
  {
    const std::string        name   = fs::path(case_file).stem().string();
    const CaseHeader         header = read_header(case_file);
    std::vector<std::string> failures;
    if (header.expect.empty())
      failures.push_back("the case has no '# expect:' first line");

    const fs::path work      = scratch / name;
    const fs::path argv_file = scratch / (name + ".argv");
    fs::create_directories(work);
    if (failures.empty() && !prepare(work, case_file, header, argv_file))
      failures.push_back("its setup or arguments could not be run by bash");
    std::vector<std::string> stderr_lines;
    if (failures.empty())
      {
        const auto before    = listing(work);
        auto       arguments = read_arguments(argv_file);
        arguments.insert(arguments.begin(), "gelmpm");
        arguments.push_back(header.scene);
        const int status = run_gelmpm(work, arguments);
        stderr_lines     = lines_of(work / "stderr");
        std::vector<std::string> wrote;
        for (const auto &path : listing(work, {"stdout", "stderr"}))
          if (!before.count(path))
            wrote.push_back(path);
        failures = refusal_failures(status, stderr_lines, header.expect, wrote);
      }

    std::cout << "input_errors/" << name << (failures.empty() ? ": PASS" : ": FAIL");
    if (!failures.empty())
      {
        for (const auto &failure : failures)
          std::cout << "\n  " << failure;
        std::cout << "\n  stderr:";
        for (const auto &line : stderr_lines)
          std::cout << "\n    " << line.substr(0, 2000);
      }
    std::cout << std::endl;
    std::error_code ignored;
    fs::remove_all(work, ignored);
    fs::remove(argv_file, ignored);
    return failures.empty();
  }
} // namespace


int
main(int argc, char **argv)
{
  if (argc < 2)
    {
      std::cerr << "usage: " << argv[0] << " CASE.prm..." << std::endl;
      return 2;
    }
  char        pattern[] = "/tmp/gelmpm_input_errors_XXXXXX";
  const char *scratch   = mkdtemp(pattern);
  if (scratch == nullptr)
    {
      std::cerr << "cannot create a scratch directory in /tmp" << std::endl;
      return 1;
    }
  unsigned int failed = 0;
  for (int i = 1; i < argc; ++i)
    failed += run_case(fs::absolute(argv[i]).string(), scratch) ? 0 : 1;
  std::error_code ignored;
  fs::remove_all(scratch, ignored);
  std::cout << argc - 1 - failed << " of " << argc - 1 << " bad-input cases passed" << std::endl;
  return failed == 0 ? 0 : 1;
}
