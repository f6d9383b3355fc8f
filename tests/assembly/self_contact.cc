// Contact of the gel with itself ('Contact/Self contact', SelfContactAssembler), a pair term, on
// one body of two blocks, [0, 1] x [0, 0.75] and [0, 1] x [1, 1.75], two cells of h = 0.125
// apart (so that no B-spline is nonzero on both), in plane strain and axisymmetric (the left side
// the axis), the facing sides the pieces that touch:
// - the point-to-segment gap: its gradient and second derivative against central differences
//   (1e-7 of their scale), and its value on a known configuration;
// - the term is in the list only when the subsection switches it on, and it makes pairs of the
//   facing sides at the setup (search distance 3 cells), which couple cells with no unknown in
//   common: the pattern holds more entries than without the term, and the next setup, with the
//   same pairs, keeps it (the linear solver keeps its analysis);
// - with the upper block's displacement unknowns at du_y = -0.3 (a rigid shift by partition of
//   unity; its bottom 0.05 behind the lower block's top) both faces' points are active, by 0.05,
//   and the pair term's y-residual summed over the upper block's unknowns is minus the reported
//   force sum A_s beta_s |g| (1e-10), over all unknowns zero (action and reaction, 1e-10 of it);
// - on that state perturbed at random, the pair term's tangent (the system's with the term less
//   the system's without it) equals the central finite-difference Jacobian of its residual to
//   1e-6 of its largest entry, and is symmetric to 1e-12 (but for the radial unknowns on the
//   axis, which the system holds at zero).
// By Nitsche's method ('Method = nitsche', the point's own traction, each face weighted by one
// half) the same checks in plane strain and axisymmetric (there the residual sums to zero over the
// axial unknowns only: a radial shift stretches the hoop, which the traction feels), and the
// tangent against the differences also for the skew-symmetric variant (not symmetric).
// 3D (check_term_3d()): two cubes, each point against the tangent plane of the nearest facing
// point, penalty and Nitsche: the same balance, the tangent of the term alone against differences
// of its residual. The same in 2D with 'Other face = tangent planes' (plane strain and
// axisymmetric, penalty and Nitsche): the pressed state's penetration and balance, the tangent
// against differences.
// A converged step is searched again at its end (SelfContactAssembler::unseen_contacts()): with one
// cell of search the blocks have no pair; the upper block shifted 0.05 through the lower one has
// points of both faces behind the other face unseen, shifted to 0.05 short of it none, and with
// the pairs of 3 cells (all active there) none either.
// The term's checks again in plane strain on a grid refined once over the left half of both
// faces (plain B-splines: the blocks are too thin for the extension's blocks of interior
// functions of both levels): pairs between points of different levels and of different leaves
// of one cell, found with the search distance in cells of the unrefined grid (3 cells; counted in
// the finest cells, 0.1875, it finds none across the gap of 0.25).
#include <gelmpm/assembly/self_contact.h>
#include <gelmpm/simulator/scene.h>

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/lac/vector.h>

#include <cmath>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <set>
#include <string>

#include "matrix_entries.h"
#include "two_blocks.h"

using namespace dealii;

namespace
{

  bool
  report(const std::string &what, const bool ok)
  {
    std::cout << "  " << what << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
    return ok;
  }


  /**
   * The two blocks 0.25 apart, with self-contact by @p method, axisymmetric or not, the Nitsche
   * variant @p variant.
   */
  struct TwoBlocks : two_blocks::TwoBlocks
  {
    TwoBlocks(const std::string &method,
              const bool         axisymmetric,
              const std::string &boxes      = "",
              const std::string &variant    = "symmetric",
              const std::string &other_face = "segments")
      : two_blocks::TwoBlocks(1.,
                              axisymmetric,
                              boxes,
                              // The pressed states lie 0.05 = 0.4 h deep: within what an iterate
                              // may reach.
                              "set Method = " + method +
                                "\nset Search distance = 3\nset Penalty = 1000\n"
                                "set Largest depth = 0.5\nset Other face = " +
                                other_face,
                              "subsection Nitsche\nset Variant = " + variant + "\nend\n")
    {}
  };


  /**
   * The upper block shifted down by @p shift, plus @p noise at random; mu_0 (plus noise) for mu.
   */
  Vector<double>
  pressed_state(const GelMPM::Scene<2> &scene, const double noise, const double shift = 0.3)
  {
    const auto    &spaces   = scene.system->spaces();
    const auto     greville = spaces.u_dof_greville_points();
    Vector<double> state    = two_blocks::noisy_state(scene, noise);
    // greville[i] of a y-component is its control point's y.
    for (unsigned int i = 1; i < spaces.n_u_dofs(); i += 2)
      if (greville[i] > 0.875)
        state(i) -= shift;
    scene.system->hold_axis(state);
    return state;
  }


  bool
  check_gap()
  {
    std::cout << "point-to-segment gap" << std::endl;
    const Point<2> x_s(0.3, -0.2), x_a(0., 0.), x_b(1., 0.1);
    const auto     gap = GelMPM::point_segment_gap(x_s, x_a, x_b);
    // The segment runs along +x (body on its right, below): outward normal up.
    const double expected = (-0.2 - 0.03) / std::sqrt(1.01);
    bool         ok = report("g below the segment (1e-14)", std::abs(gap.g - expected) < 1e-14);
    double       error_1 = 0., error_2 = 0., scale_2 = 0.;
    const double h = 1e-5;
    for (unsigned int k = 0; k < 6; ++k)
      {
        Point<2> p[3] = {x_s, x_a, x_b}, m[3] = {x_s, x_a, x_b};
        p[k / 2][k % 2] += h;
        m[k / 2][k % 2] -= h;
        const auto plus  = GelMPM::point_segment_gap(p[0], p[1], p[2]);
        const auto minus = GelMPM::point_segment_gap(m[0], m[1], m[2]);
        error_1 = std::max(error_1, std::abs((plus.g - minus.g) / (2. * h) - gap.gradient[k]));
        for (unsigned int l = 0; l < 6; ++l)
          {
            error_2 = std::max(error_2,
                               std::abs((plus.gradient[l] - minus.gradient[l]) / (2. * h) -
                                        gap.hessian[k][l]));
            scale_2 = std::max(scale_2, std::abs(gap.hessian[k][l]));
          }
      }
    ok &= report("gradient = central differences (1e-7)", error_1 < 1e-7);
    ok &= report("second derivative = central differences (1e-7)", error_2 < 1e-7 * scale_2);
    return ok;
  }


  bool
  check_term(const bool         axisymmetric,
             const std::string &boxes      = "",
             const std::string &method     = "penalty",
             const std::string &variant    = "symmetric",
             const std::string &other_face = "segments")
  {
    std::cout << method << (method == "nitsche" ? " (" + variant + ")" : "") << ", "
              << (axisymmetric ? "axisymmetric" : "plane strain")
              << (boxes.empty() ? "" : ", refined " + boxes)
              << (other_face == "segments" ? "" : ", " + other_face) << std::endl;
    TwoBlocks on(method, axisymmetric, boxes, variant, other_face),
      off("none", axisymmetric, boxes, variant);
    auto        &system = *on.scene->system, &plain = *off.scene->system;
    const double dt = 0.05;
    bool         ok = report("no self-contact term when off",
                     plain.assemblers().size() == 3 && system.assemblers().size() == 4);
    const auto  *term =
      dynamic_cast<const GelMPM::SelfContactAssembler<2> *>(system.assemblers().back());
    std::cout << "  " << term->n_pairs() << " pairs" << std::endl;
    ok &= report("pairs found at the setup", term->n_pairs() > 0);
    ok &= report("their cells' entries in the pattern (more entries than without)",
                 system.matrix().n_nonzero_elements() > plain.matrix().n_nonzero_elements());
    ok &= report("the next setup keeps the pattern (the same pairs)",
                 !system.setup(on.scene->particles));
    system.set_boundary_values(0.5, 0.);

    // Exact shift: both faces flat, every active point by 0.05.
    const Vector<double> shifted = pressed_state(*on.scene, 0.);
    const auto           state   = system.self_contact_state(shifted);
    std::cout << "  " << state.points << " points active, force " << state.force << std::endl;
    ok &= report("active points on both faces, penetration 0.05 (1e-12)",
                 state.points > 0 && std::abs(state.penetration - 0.05) < 1e-12);
    system.assemble(shifted, dt, false);
    plain.assemble(shifted, dt, false);
    const auto greville = system.spaces().u_dof_greville_points();
    double     upper = 0., total_y = 0., total_x = 0.;
    for (unsigned int i = 0; i < system.spaces().n_u_dofs(); ++i)
      {
        const double r = system.residual()(i) - plain.residual()(i);
        (i % 2 == 0 ? total_x : total_y) += r;
        if (i % 2 == 1 && greville[i] > 0.875)
          upper += r;
      }
    ok &= report("upper block's y-residual = -force (1e-10)",
                 std::abs(upper + state.force) < 1e-10 * state.force);
    // A rigid shift leaves the term unchanged: its residual sums to zero over each component's
    // unknowns. Not so for a radial shift of an axisymmetric body under Nitsche's method: it
    // stretches the hoop, which the point's traction feels (the penalty's does not).
    const bool radial_shift_rigid = !(axisymmetric && method == "nitsche");
    ok &= report(radial_shift_rigid ? "sum over all unknowns zero (1e-10 of the force)"
                                    : "sum over all axial unknowns zero (1e-10 of the force)",
                 (!radial_shift_rigid || std::abs(total_x) < 1e-10 * state.force) &&
                   std::abs(total_y) < 1e-10 * state.force);

    // The tangent of the pair term alone against differences of its residual.
    const Vector<double> perturbed = pressed_state(*on.scene, 2e-3);
    const unsigned int   n         = system.spaces().n_dofs();
    system.assemble(perturbed, dt, true);
    plain.assemble(perturbed, dt, true);
    const MatrixEntries K(system.matrix()), K_plain(plain.matrix());
    // The radial unknowns on the axis stay zero: their rows and columns hold the diagonal only.
    std::vector<bool> on_axis(n, false);
    for (const auto i : system.spaces().axis_unknowns())
      on_axis[i] = true;
    double error = 0., largest = 0., asymmetry = 0.;
    for (unsigned int j = 0; j < n; ++j)
      {
        if (on_axis[j])
          continue;
        const double   h = j < system.spaces().n_u_dofs() ? 1e-7 : 1e-6;
        Vector<double> plus(perturbed), minus(perturbed);
        plus(j) += h;
        minus(j) -= h;
        system.assemble(plus, dt, false);
        plain.assemble(plus, dt, false);
        Vector<double> fd(system.residual());
        fd -= plain.residual();
        system.assemble(minus, dt, false);
        plain.assemble(minus, dt, false);
        fd -= system.residual();
        fd += plain.residual();
        fd /= 2. * h;
        for (unsigned int i = 0; i < n; ++i)
          {
            if (on_axis[i])
              continue;
            const double k_ij = K.at(i, j) - K_plain.at(i, j);
            error             = std::max(error, std::abs(k_ij - fd(i)));
            largest           = std::max(largest, std::abs(k_ij));
            asymmetry = std::max(asymmetry, std::abs(k_ij - (K.at(j, i) - K_plain.at(j, i))));
          }
      }
    std::cout << "  " << system.self_contact_state(perturbed).points
              << " points active on the perturbed state" << std::endl;
    ok &= report("|K - K_fd| / max|K| < 1e-6", largest > 0. && error <= 1e-6 * largest);
    if (variant == "symmetric")
      ok &= report("symmetric to 1e-12", asymmetry <= 1e-12 * largest);
    else
      ok &= report("not symmetric (the skew-symmetric variant)", asymmetry > 1e-6 * largest);
    return ok;
  }


  /**
   * The pair term's residual and its entries on the unknowns of @p state, from the term alone
   * (its local systems, summed).
   */
  template <int dim>
  std::pair<Vector<double>, std::map<std::pair<unsigned int, unsigned int>, double>>
  term_system(const GelMPM::SelfContactAssembler<dim> &term,
              const GelMPM::MixedSystem<dim>          &system,
              const Vector<double>                    &state,
              const bool                               with_matrix)
  {
    std::vector<GelMPM::AssemblyCopy> copies;
    term.assemble_beyond_blocks(system.point_cache(), state, 0.05, with_matrix, copies);
    Vector<double>                                          residual(state.size());
    std::map<std::pair<unsigned int, unsigned int>, double> entries;
    for (const auto &copy : copies)
      for (unsigned int i = 0; i < copy.dofs.size(); ++i)
        {
          residual(copy.dofs[i]) += copy.residual(i);
          for (unsigned int j = 0; j < copy.dofs.size() && with_matrix; ++j)
            entries[{copy.dofs[i], copy.dofs[j]}] += copy.matrix(i, j);
        }
    return {residual, entries};
  }


  /**
   * 3D: two cubes of one body 0.25 (two cells) apart along z, the facing sides the pieces, each
   * point against the tangent plane of the nearest facing point; the term alone (its residual
   * from its local systems): pressed 0.05 into each other, the upper cube's z-residual is minus
   * the reported force and every component sums to zero over all unknowns (1e-10); on that state
   * perturbed, its tangent equals the central differences of its residual (1e-6 of its largest
   * entry, on every eighth unknown it couples) and is symmetric (1e-12) for the penalty and the
   * symmetric Nitsche variant.
   */
  bool
  check_term_3d(const std::string &method)
  {
    std::cout << method << ", 3D" << std::endl;
    ParameterHandler               prm;
    const std::vector<std::string> pieces = {"lower_top", "upper_bottom", "rest"};
    GelMPM::Scene<3>::declare_parameters(prm, pieces);
    prm.parse_input_from_string(
      "subsection Background grid\nset Lower corner = -0.25, -0.25, -0.25\n"
      "set Upper corner = 0.75, 0.75, 1.25\nset Cells = 8, 8, 12\nend\n"
      "subsection Geometry\nset Boxes = 0, 0, 0 : 0.5, 0.5, 0.375; 0, 0, 0.625 : 0.5, 0.5, 1\n"
      "end\nsubsection Discretisation\nset Extended B-splines = false\nend\nsubsection Material points\nset Points per cell = 3\nend\n"
      "subsection Boundary conditions\n"
      "subsection lower_top\nset Selector = nz > 0.5 && z < 0.5\nend\n"
      "subsection upper_bottom\nset Selector = nz < -0.5 && z > 0.5\nend\n"
      "subsection rest\nset Selector = x > -1\nend\nend\n"
      "subsection Contact\nsubsection Self contact\nset Pieces = lower_top, upper_bottom\n"
      "set Method = " +
      method +
      "\nset Search distance = 2.2\nset Penalty = 1000\nset Largest depth = 0.5\n"
      "set Separate faces = false\nend\nend\n");
    GelMPM::Scene<3> scene(prm, pieces);
    scene.create_material_points();
    scene.create_system();
    auto &system = *scene.system;
    system.setup(scene.particles);
    system.set_boundary_values(0.5, 0.);
    const auto *term =
      dynamic_cast<const GelMPM::SelfContactAssembler<3> *>(system.assemblers().back());
    bool ok = report("the term in the list, pairs found", term != nullptr && term->n_pairs() > 0);
    if (!ok)
      return false;

    const auto &spaces   = system.spaces();
    const auto  greville = spaces.u_dof_greville_points();
    const auto  pressed  = [&](const double noise) {
      Vector<double> state = two_blocks::noisy_state(scene, noise);
      // greville[i] of a z-component is its control point's z.
      for (unsigned int i = 2; i < spaces.n_u_dofs(); i += 3)
        if (greville[i] > 0.5)
          state(i) -= 0.3;
      return state;
    };
    const Vector<double> shifted = pressed(0.);
    const auto           state   = term->state(system.point_cache(), shifted);
    std::cout << "  " << term->n_pairs() << " pairs, " << state.points << " points active"
              << std::endl;
    ok &= report("active points on both faces, penetration 0.05 (1e-12)",
                 state.points > 0 && std::abs(state.penetration - 0.05) < 1e-12);
    const auto [residual, unused] = term_system(*term, system, shifted, false);
    (void)unused;
    double upper = 0., total[3] = {};
    for (unsigned int i = 0; i < spaces.n_u_dofs(); ++i)
      {
        total[i % 3] += residual(i);
        if (i % 3 == 2 && greville[i] > 0.5)
          upper += residual(i);
      }
    ok &= report("upper cube's z-residual = -force (1e-10)",
                 std::abs(upper + state.force) < 1e-10 * state.force);
    ok &=
      report("sum over all unknowns zero (1e-10 of the force)",
             std::abs(total[0]) < 1e-10 * state.force && std::abs(total[1]) < 1e-10 * state.force &&
               std::abs(total[2]) < 1e-10 * state.force);

    const Vector<double> perturbed = pressed(2e-3);
    const auto [r0, K]             = term_system(*term, system, perturbed, true);
    (void)r0;
    std::set<unsigned int> columns;
    for (const auto &[ij, k] : K)
      columns.insert(ij.second);
    // Every eighth column the term couples (8 and the 3 components coprime: every kind of
    // unknown among them); the differences cost two assemblies of the term each.
    double       error = 0., largest = 0., asymmetry = 0.;
    unsigned int count = 0;
    for (const unsigned int j : columns)
      {
        if (count++ % 8 != 0)
          continue;
        const double   h = j < spaces.n_u_dofs() ? 1e-7 : 1e-6;
        Vector<double> plus(perturbed), minus(perturbed);
        plus(j) += h;
        minus(j) -= h;
        Vector<double> fd = term_system(*term, system, plus, false).first;
        fd -= term_system(*term, system, minus, false).first;
        fd /= 2. * h;
        for (const unsigned int i : columns)
          {
            const auto   ij  = K.find({i, j});
            const auto   ji  = K.find({j, i});
            const double kij = ij == K.end() ? 0. : ij->second;
            const double kji = ji == K.end() ? 0. : ji->second;
            error            = std::max(error, std::abs(kij - fd(i)));
            largest          = std::max(largest, std::abs(kij));
            asymmetry        = std::max(asymmetry, std::abs(kij - kji));
          }
      }
    std::cout << "  " << term->state(system.point_cache(), perturbed).points
              << " points active on the perturbed state" << std::endl;
    ok &= report("|K - K_fd| / max|K| < 1e-6", largest > 0. && error <= 1e-6 * largest);
    ok &= report("symmetric to 1e-12", asymmetry <= 1e-12 * largest);
    return ok;
  }


  bool
  check_unseen()
  {
    std::cout << "a face passed unseen (plane strain)" << std::endl;
    // One cell of search: across the gap of two cells the step has no pair.
    two_blocks::TwoBlocks blocks(1.,
                                 false,
                                 "",
                                 "set Method = penalty\nset Search distance = 1\n"
                                 "set Largest depth = 0.5");
    const auto           &system = *blocks.scene->system;
    const auto           *term =
      dynamic_cast<const GelMPM::SelfContactAssembler<2> *>(system.assemblers().back());
    bool               ok      = report("no pairs at the setup", term->n_pairs() == 0);
    const unsigned int through = system.unseen_self_contacts(pressed_state(*blocks.scene, 0.));
    const unsigned int short_of =
      system.unseen_self_contacts(pressed_state(*blocks.scene, 0., 0.2));
    std::cout << "  points through the other face unseen: " << through << " (0.05 through), "
              << short_of << " (0.05 short of it)" << std::endl;
    ok &=
      report("the upper block 0.05 through the lower: points of both faces unseen", through > 0);
    ok &= report("0.05 short of it: none", short_of == 0);
    TwoBlocks  seen("penalty", false);
    const auto n_seen = seen.scene->system->unseen_self_contacts(pressed_state(*seen.scene, 0.));
    ok &= report("with the step's pairs (3 cells of search) active there: none", n_seen == 0);
    return ok;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                             ok = check_gap();
  ok &= check_term(false);
  ok &= check_term(true);
  ok &= check_term(false, "0, 0.25 : 0.5, 1.5");
  ok &= check_term(false, "", "nitsche");
  ok &= check_term(true, "", "nitsche");
  ok &= check_term(false, "", "nitsche", "skew-symmetric");
  for (const bool axisymmetric : {false, true})
    for (const std::string method : {"penalty", "nitsche"})
      ok &= check_term(axisymmetric, "", method, "symmetric", "tangent planes");
  ok &= check_term_3d("penalty");
  ok &= check_term_3d("nitsche");
  ok &= check_unseen();
  std::cout << (ok ? "self-contact checks passed" : "SELF-CONTACT CHECKS FAILED") << std::endl;
  return ok ? 0 : 1;
}
