// 'Background grid/Refinement grading': the refined domains of several levels are widened so
// that at most two levels of truncated functions are nonzero on any leaf cell (class-2
// admissible THB-splines), for u and mu, against the same marks ungraded:
// - cases: a small box refined 3 times (Q2-Q2SD, 2D), the same box with Q3-Q3SD and with mu on
//   u's grid (Q2-Q2), a ring refined 4 times (the region), and a 3D box refined 3 times;
// - graded: every leaf of both hierarchies carries functions of at most two successive levels;
//   ungraded (the control): some leaf of every case carries three or more, so the check can fail;
// - grading only adds refined cells (the criteria's cells stay refined) and the domains nest;
// - the graded basis still sums to one (1e-12) at points of every leaf.
#include <gelmpm/assembly/discretisation.h>
#include <gelmpm/bspline/hierarchical_bspline_space.h>
#include <gelmpm/scene/background_grid.h>

#include <deal.II/base/parameter_handler.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

namespace
{
  bool
  report(const std::string &what, const bool ok)
  {
    std::cout << "  " << what << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
    return ok;
  }


  /** The largest number of levels of the functions nonzero on one leaf of @p space. */
  template <int dim>
  unsigned int
  most_levels_on_a_leaf(const GelMPM::HierarchicalBSplineSpace<dim> &space)
  {
    unsigned int most = 0;
    for (unsigned int leaf = 0; leaf < space.n_leaf_cells(); ++leaf)
      {
        unsigned int lowest = space.n_levels(), highest = 0;
        for (const unsigned int i : space.leaf_functions(leaf))
          {
            lowest  = std::min(lowest, space.active_function(i).level);
            highest = std::max(highest, space.active_function(i).level);
          }
        most = std::max(most, highest - lowest + 1);
      }
    return most;
  }


  /** The largest |sum of values - 1| at the centres and a corner-near point of every leaf. */
  template <int dim>
  double
  partition_of_unity_error(const GelMPM::HierarchicalBSplineSpace<dim> &space)
  {
    double                              error = 0.;
    std::vector<double>                 values;
    std::vector<dealii::Tensor<1, dim>> gradients;
    for (unsigned int leaf = 0; leaf < space.n_leaf_cells(); ++leaf)
      {
        const auto &cell  = space.leaf_cell(leaf);
        const auto &level = space.level_space(cell.level);
        const auto  index = level.cell_multi_index(cell.cell);
        for (const double fraction : {0.5, 0.1})
          {
            dealii::Point<dim> p;
            for (unsigned int d = 0; d < dim; ++d)
              p[d] = level.basis_1d(d).x_min() + (index[d] + fraction) * level.cell_size(d);
            space.evaluate(p, leaf, values, gradients);
            double sum = 0.;
            for (const double v : values)
              sum += v;
            error = std::max(error, std::abs(sum - 1.));
          }
      }
    return error;
  }


  struct Hierarchies
  {
    unsigned int most_mu = 0, most_u = 0, refined_cells = 0;
    double       unity = 0.;
    /** Per level, the refined cells of the grid of pairs. */
    std::vector<std::vector<unsigned int>> pair_cells;
  };


  template <int dim>
  Hierarchies
  build(const std::string &grid_entries, const std::string &discretisation, const bool grading)
  {
    dealii::ParameterHandler prm;
    GelMPM::BackgroundGrid<dim>::declare_parameters(prm);
    GelMPM::DiscretisationSettings::declare_parameters(prm);
    prm.parse_input_from_string("subsection Background grid\n" + grid_entries +
                                "\n set Refinement grading = " + (grading ? "true" : "false") +
                                "\nend\nsubsection Discretisation\n" + discretisation + "\nend\n");
    GelMPM::BackgroundGrid<dim> grid;
    grid.parse_parameters(prm);
    GelMPM::DiscretisationSettings settings;
    settings.parse_parameters(prm);
    grid.set_grading_reach(settings.support_reach_in_pair_cells());

    Hierarchies                   result;
    std::array<unsigned int, dim> pairs;
    for (unsigned int d = 0; d < dim; ++d)
      pairs[d] = grid.n_cells[d] / 2;
    result.pair_cells = grid.refined_pair_cells();
    for (const auto &level : result.pair_cells)
      result.refined_cells += level.size();
    // As DiscreteSpaces builds them: mu's marks on the grid of pairs, u's from them.
    const GelMPM::HierarchicalBSplineSpace<dim> pair_space(settings.chemical_potential_degree,
                                                           grid.lower,
                                                           grid.upper,
                                                           pairs,
                                                           result.pair_cells);
    const auto u_cells = GelMPM::subdivision_refinement(pair_space);
    const GelMPM::HierarchicalBSplineSpace<dim> u(settings.displacement_degree,
                                                  grid.lower,
                                                  grid.upper,
                                                  grid.n_cells,
                                                  u_cells);
    const GelMPM::HierarchicalBSplineSpace<dim> mu_same(settings.chemical_potential_degree,
                                                        grid.lower,
                                                        grid.upper,
                                                        grid.n_cells,
                                                        u_cells);
    const auto                                 &mu = settings.subdivision ? pair_space : mu_same;
    result.most_mu                                 = most_levels_on_a_leaf(mu);
    result.most_u                                  = most_levels_on_a_leaf(u);
    result.unity = std::max(partition_of_unity_error(mu), partition_of_unity_error(u));
    return result;
  }


  template <int dim>
  bool
  check(const std::string &name, const std::string &grid_entries, const std::string &pair)
  {
    std::cout << name << std::endl;
    const auto graded   = build<dim>(grid_entries, pair, true);
    const auto ungraded = build<dim>(grid_entries, pair, false);
    std::cout << "  refined cell pairs: " << ungraded.refined_cells << " ungraded, "
              << graded.refined_cells << " graded" << std::endl;
    std::cout << "  most levels on a leaf (mu, u): ungraded " << ungraded.most_mu << ", "
              << ungraded.most_u << "; graded " << graded.most_mu << ", " << graded.most_u
              << std::endl;
    bool ok =
      report("graded: at most two levels on every leaf", graded.most_mu <= 2 && graded.most_u <= 2);
    ok &= report("ungraded: three or more on some leaf",
                 std::max(ungraded.most_mu, ungraded.most_u) >= 3);
    bool superset = true;
    for (unsigned int l = 0; l < ungraded.pair_cells.size(); ++l)
      for (const unsigned int c : ungraded.pair_cells[l])
        superset &= std::binary_search(graded.pair_cells[l].begin(), graded.pair_cells[l].end(), c);
    ok &= report("grading only adds refined cells", superset);
    ok &= report("the graded basis sums to one (1e-12)", graded.unity <= 1e-12);
    return ok;
  }
} // namespace


int
main()
{
  const std::string box = " set Lower corner = 0, 0\n set Upper corner = 4, 4\n"
                          " set Cells = 32, 32\n set Refinement boxes = 1.9, 1.9 : 2.1, 2.1\n"
                          " set Refinement levels = 3";
  bool              ok  = check<2>("2D box, 3 levels, Q2-Q2SD", box, "");
  ok &= check<2>("2D box, 3 levels, Q3-Q3SD",
                 box,
                 " set Displacement degree = 3\n set Chemical potential degree = 3");
  ok &= check<2>("2D box, 3 levels, Q2-Q2 (mu on u's grid)",
                 box,
                 " set Chemical potential grid = same");
  ok &= check<2>("2D ring, 4 levels, Q2-Q2SD",
                 " set Lower corner = 0, 0\n set Upper corner = 4, 4\n set Cells = 32, 32\n"
                 " set Refinement region = abs(sqrt((x - 2)^2 + (y - 2)^2) - 1) - 0.02\n"
                 " set Refinement levels = 4",
                 "");
  ok &= check<3>("3D box, 3 levels, Q2-Q2SD",
                 " set Lower corner = 0, 0, 0\n set Upper corner = 2, 2, 2\n"
                 " set Cells = 16, 16, 16\n set Refinement boxes = 0.9, 0.9, 0.9 : 1.1, 1.1, 1.1\n"
                 " set Refinement levels = 3",
                 "");
  std::cout << (ok ? "OK" : "FAILED") << std::endl;
  return ok ? 0 : 1;
}
