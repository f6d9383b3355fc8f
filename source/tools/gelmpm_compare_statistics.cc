// gelmpm-compare-statistics: whether two statistics.csv files of runs of one scene agree, column
// by column, within tolerances that say what each kind of column can be expected to reproduce.
// Used by the tests that compare a run on several MPI ranks with the run on one, and by users
// who compare two runs (e.g. before and after a change of machine or library).

#include <gelmpm/io/statistics_file.h>

#include <algorithm>
#include <boost/program_options.hpp>
#include <cmath>
#include <functional>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace
{
  namespace po = boost::program_options;

  struct Tolerances
  {
    double      relative    = 1e-10;
    double      eigenvalues = 1e-8;
    double      newton      = 1.;
    std::string ignore      = "residual_u,residual_mu,solvent_imbalance,wall_time";
  };

  /** The columns that count things or mark the step sequence: they must be equal. */
  bool
  is_exact(const std::string &column)
  {
    static const std::set<std::string> exact = {"step",
                                                "time",
                                                "t_over_tau_d",
                                                "dt",
                                                "attempts",
                                                "n_dofs_u",
                                                "n_dofs_mu",
                                                "n_active_cells",
                                                "n_particles",
                                                "n_pos",
                                                "n_neg",
                                                "n_zero",
                                                "n_neg_uu",
                                                "contact_points"};
    return exact.count(column) > 0 || column.rfind("pore_creases_", 0) == 0 ||
           column.rfind("pore_contact_", 0) == 0;
  }

  /**
   * The columns whose scale a column shares: the forces, the inflows and the solvent taken in of
   * all the boundary pieces (P_force_x, P_inflow, P_solvent_in, ...), each kind against the
   * largest of its kind. A piece's column that is round-off against the body's (the force
   * across a frictionless punch, the solvent through an impermeable piece) is judged on the
   * body's scale, as its sum with the others is. Else the column alone.
   */
  std::vector<std::string>
  scale_group(const std::string &column, const std::map<std::string, std::vector<double>> &all)
  {
    const auto ends_with = [](const std::string &text, const std::string &end) {
      return text.size() >= end.size() &&
             text.compare(text.size() - end.size(), end.size(), end) == 0;
    };
    const auto is_force = [&](const std::string &c) {
      return ends_with(c, "_force_x") || ends_with(c, "_force_y") || ends_with(c, "_force_z");
    };
    for (const auto &kind :
         std::vector<std::function<bool(const std::string &)>>{is_force,
                                                               [&](const std::string &c) {
                                                                 return ends_with(c, "_inflow");
                                                               },
                                                               [&](const std::string &c) {
                                                                 return ends_with(c, "_solvent_in");
                                                               }})
      if (kind(column))
        {
          std::vector<std::string> group;
          for (const auto &[name, values] : all)
            if (kind(name))
              group.push_back(name);
          return group;
        }
    return {column};
  }


  bool
  equal_or_both_nan(const double a, const double b)
  {
    return a == b || (std::isnan(a) && std::isnan(b));
  }
} // namespace


int
main(int argc, char **argv)
{
  Tolerances              tolerances;
  std::string             first_file, second_file;
  po::options_description options(
    "Usage: gelmpm-compare-statistics [options] first.csv second.csv\n\n"
    "Compares two statistics.csv files of one scene column by column and says, per column, the\n"
    "largest difference and whether it is within its tolerance. Counts, times and step sizes\n"
    "(step, time, dt, attempts, n_dofs_*, n_particles, the inertia n_pos/n_neg/n_zero, ...) must\n"
    "be equal; newton_iterations may differ by --newton; eig_* columns (ARPACK) agree to\n"
    "--eigenvalues relative; every other column to --relative times its largest magnitude\n"
    "over the rows (a column that is a small difference of large numbers is judged against\n"
    "its own scale; the boundary pieces' forces, inflows and solvent taken in each against the\n"
    "largest of their kind). Exit status 0 when all agree, 1 otherwise, 2 on bad input.\n\nOptions");
  options.add_options()("help,h", "this message")(
    "relative",
    po::value(&tolerances.relative)->default_value(tolerances.relative),
    "tolerance of the physical columns, relative to the column's largest magnitude")(
    "eigenvalues",
    po::value(&tolerances.eigenvalues)->default_value(tolerances.eigenvalues),
    "relative tolerance of the Schur-complement eigenvalues eig_*")(
    "newton",
    po::value(&tolerances.newton)->default_value(tolerances.newton),
    "largest difference of newton_iterations in a step")(
    "ignore",
    po::value(&tolerances.ignore)->default_value(tolerances.ignore),
    "comma-separated columns not compared (the converged residuals and the mass balance "
    "solvent_imbalance are round-off, wall_time a machine's)");
  po::options_description hidden;
  hidden.add_options()("first", po::value(&first_file))("second", po::value(&second_file));
  po::options_description all;
  all.add(options).add(hidden);
  po::positional_options_description positional;
  positional.add("first", 1).add("second", 1);
  try
    {
      po::variables_map vm;
      po::store(po::command_line_parser(argc, argv).options(all).positional(positional).run(), vm);
      po::notify(vm);
      if (vm.count("help"))
        {
          std::cout << options << std::endl;
          return 0;
        }
      if (first_file.empty() || second_file.empty())
        {
          std::cerr << "gelmpm-compare-statistics: give two statistics.csv files\n"
                    << options << std::endl;
          return 2;
        }
    }
  catch (const std::exception &e)
    {
      std::cerr << "gelmpm-compare-statistics: " << e.what() << std::endl;
      return 2;
    }

  std::map<std::string, std::vector<double>> first, second;
  try
    {
      first  = GelMPM::read_statistics(first_file);
      second = GelMPM::read_statistics(second_file);
    }
  catch (const std::exception &e)
    {
      std::cerr << "gelmpm-compare-statistics: " << e.what() << std::endl;
      return 2;
    }

  std::set<std::string> ignored;
  for (std::size_t begin = 0; begin <= tolerances.ignore.size();)
    {
      const std::size_t end =
        std::min(tolerances.ignore.find(',', begin), tolerances.ignore.size());
      if (end > begin)
        ignored.insert(tolerances.ignore.substr(begin, end - begin));
      begin = end + 1;
    }

  bool agree = true;
  for (const auto &[column, a] : first)
    {
      const auto found = second.find(column);
      if (found == second.end())
        {
          std::cout << "FAIL " << column << ": only in " << first_file << '\n';
          agree = false;
          continue;
        }
      const auto &b = found->second;
      if (a.size() != b.size())
        {
          std::cout << "FAIL " << column << ": " << a.size() << " rows against " << b.size()
                    << '\n';
          agree = false;
          continue;
        }
      if (ignored.count(column))
        continue;
      double scale = 0., largest = 0.;
      bool   equal = true;
      for (std::size_t i = 0; i < a.size(); ++i)
        {
          equal = equal && equal_or_both_nan(a[i], b[i]);
          if (!std::isnan(a[i]) && !std::isnan(b[i]))
            largest = std::max(largest, std::abs(a[i] - b[i]));
          else if (std::isnan(a[i]) != std::isnan(b[i]))
            largest = std::numeric_limits<double>::infinity();
        }
      for (const auto &member : scale_group(column, first))
        for (const double v : first.at(member))
          if (!std::isnan(v))
            scale = std::max(scale, std::abs(v));
      for (const double v : b)
        if (!std::isnan(v))
          scale = std::max(scale, std::abs(v));
      bool        ok = true;
      std::string rule;
      if (is_exact(column))
        {
          ok   = equal;
          rule = "equal";
        }
      else if (column == "newton_iterations")
        {
          ok   = largest <= tolerances.newton;
          rule = "within " + std::to_string(static_cast<int>(tolerances.newton));
        }
      else
        {
          const double relative =
            column.rfind("eig_", 0) == 0 ? tolerances.eigenvalues : tolerances.relative;
          ok = largest <= relative * scale;
          std::ostringstream text;
          text << "within " << relative << " x " << scale;
          rule = text.str();
        }
      std::cout << (ok ? "ok   " : "FAIL ") << std::left << std::setw(24) << column
                << " largest difference " << std::setw(12) << largest << " (" << rule << ")\n";
      agree = agree && ok;
    }
  for (const auto &[column, values] : second)
    if (first.count(column) == 0)
      {
        std::cout << "FAIL " << column << ": only in " << second_file << '\n';
        agree = false;
      }
  std::cout << (agree ? "the two files agree" : "the two files differ") << std::endl;
  return agree ? 0 : 1;
}
