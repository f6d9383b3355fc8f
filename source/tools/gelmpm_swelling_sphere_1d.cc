// gelmpm-swelling-sphere-1d: the finite-difference reference for a freely swelling gel sphere.
// Prints the outer radius r(R_0, t)/R_0 at the requested times as CSV on stdout, and writes the
// radius against time and the fields at the requested times as CSV files; see
// doc/free_swelling_sphere.md for the equations and a convergence study.
#include <gelmpm/reference/free_swelling_sphere_1d.h>
#include <gelmpm/reference/tool_times.h>

#include <algorithm>
#include <boost/program_options.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <set>
#include <sstream>


int
main(int argc, char **argv)
{
  namespace po = boost::program_options;
  GelMPM::FreeSwellingSphere1D::Parameters parameters;
  std::string                              times_text, directory;
  unsigned int                             n_samples;
  po::options_description                  options(
    "gelmpm-swelling-sphere-1d: finite-difference reference for a freely swelling gel sphere.\n"
                     "Lengths in R_0 (initial radius), times in tau_d = R_0^2/D, mu in k_BT.\nOptions");
  options.add_options()("help", "this text")("cells",
                                             po::value(&parameters.n_cells)->default_value(400),
                                             "finite-volume cells along the radius")(
    "grading",
    po::value(&parameters.grading)->default_value(2.),
    "node grading towards the surface, R_i = 1 - (1 - i/n)^g")(
    "first-step",
    po::value(&parameters.first_step)->default_value(1e-9),
    "first time step")("growth",
                       po::value(&parameters.growth)->default_value(1.01),
                       "growth factor of consecutive time steps")(
    "chi",
    po::value(&parameters.chi)->default_value(0.1),
    "Flory-Huggins chi")("N-nu",
                         po::value(&parameters.N_nu)->default_value(7.299e-3),
                         "N nu")("lambda-0",
                                 po::value(&parameters.lambda_0)->default_value(1.2801),
                                 "initial isotropic stretch from the dry state")(
    "mu-top",
    po::value(&parameters.mu_top)->default_value(0.),
    "mu/k_BT of the bath for t > 0 (after the ramp)")(
    "ramp",
    po::value(&parameters.ramp)->default_value(0.),
    "time over which the bath's mu rises linearly from mu_0 (the initial state's) to mu-top; 0: "
    "a step at t = 0+")("times",
                        po::value(&times_text)->default_value("0.1,1,4,10,100"),
                        "comma-separated times of the printed radii and of the profiles; the last "
                        "one ends the run")(
    "samples",
    po::value(&n_samples)->default_value(400),
    "log-spaced times of the radius curve, from 1e-6 to the end (0: only --times)")(
    "output",
    po::value(&directory)->default_value("output/swelling_sphere_1d"),
    "output directory");

  try
    {
      po::variables_map vm;
      po::store(po::parse_command_line(argc, argv, options), vm);
      if (vm.count("help"))
        {
          std::cout << options << std::endl;
          return 0;
        }
      po::notify(vm);
      const std::vector<double> profile_times = GelMPM::parse_positive_times(times_text);
      const double              end = *std::max_element(profile_times.begin(), profile_times.end());

      std::set<double> times(profile_times.begin(), profile_times.end());
      for (unsigned int k = 0; k < n_samples; ++k)
        {
          const double t = 1e-6 * std::pow(end / 1e-6, (k + 1.) / n_samples);
          if (t < end)
            times.insert(t);
        }

      GelMPM::FreeSwellingSphere1D reference(parameters);
      std::filesystem::create_directories(directory);
      std::ofstream radius(directory + "/reference_radius.csv");
      std::ofstream profiles(directory + "/reference_profiles.csv");
      radius << "t_over_tau_d,r_over_R0,mu_bath_over_kT,solvent_uptake\n" << std::setprecision(12);
      profiles << "t_over_tau_d,R_over_R0,r_over_R0,lambda_r,lambda_theta,mu_over_kT,s_r,s_theta\n"
               << std::setprecision(12);
      std::cout << "t_over_tau_d,r_over_R0\n" << std::setprecision(10);
      for (const double t : times)
        {
          reference.advance_to(t);
          radius << t << ',' << reference.outer_radius() << ','
                 << reference.bath_chemical_potential(t) << ',' << reference.solvent_uptake()
                 << '\n';
          if (std::find(profile_times.begin(), profile_times.end(), t) != profile_times.end())
            {
              // The fields at the cell centres (r there: the mean of the cell's two nodes).
              const auto  R_c = reference.cell_centres();
              const auto &r   = reference.radii();
              const auto &mu  = reference.chemical_potentials();
              const auto  l_r = reference.radial_stretches(), l_t = reference.hoop_stretches();
              const auto  s_r = reference.radial_stresses(), s_t = reference.hoop_stresses();
              for (unsigned int k = 0; k < R_c.size(); ++k)
                profiles << t << ',' << R_c[k] << ',' << 0.5 * (r[k] + r[k + 1]) << ',' << l_r[k]
                         << ',' << l_t[k] << ',' << mu[k] << ',' << s_r[k] << ',' << s_t[k] << '\n';
              std::cout << t << ',' << reference.outer_radius() << std::endl;
            }
        }
      std::cout << "# gelmpm-swelling-sphere-1d: " << reference.n_steps()
                << " steps; equilibrium r/R_0 = " << reference.stretch_at(parameters.mu_top)
                << " (isotropic free swelling at mu = mu_top); results: " << directory
                << "/reference_radius.csv, " << directory << "/reference_profiles.csv" << std::endl;
    }
  catch (const std::exception &e)
    {
      std::cerr << "gelmpm-swelling-sphere-1d: " << e.what() << std::endl;
      return 2;
    }
  return 0;
}
