// Contact with a plane of symmetry (ContactSettings) on the assembly scene, its grid cut at
// y = 1.25 above the body's top (y = 1.1, a free piece), the top side of the grid a contact
// plane:
// - at rest nothing touches; lifted by du = 0.2 e_y (a constant, exact in the extended basis)
//   every top surface point penetrates by 0.05;
// - penalty: the contact force, the y-residual summed over all functions (a partition of unity),
//   equals sum_s A_s beta_c g_s over the top points computed from the points themselves (1e-10);
// - penalty and Nitsche: the tangent equals a central finite-difference Jacobian of the residual
//   at a perturbed lifted state (1e-6 of the largest entry), and is symmetric (1e-12).
// - a rigid obstacle on that plane, its active set held for Newton's iterations under Nitsche's
//   method (MixedSystem::freeze_switches(), PointRecord::contact_held): held at rest (nothing
//   touches) the lifted state assembles no contact force although its points are in contact,
//   and counts each of them as a changed switch; released, the lifted state has the iterate's
//   force; held at the lifted state, the state at rest has contact terms where following it
//   gives none. With the penalty nothing is held: the iterate's force, no switch counted.
#include <gelmpm/particles/property_layout.h>

#include <deal.II/lac/full_matrix.h>

#include <cmath>
#include <iostream>
#include <random>

#include "scene_fixture.h"

using namespace dealii;
using GelMPM::ContactSettings;

namespace
{
  const std::string grid_below_plane = R"(
    subsection Background grid
      set Upper corner = 2, 1.25
      set Cells = 24, 18
    end)";
  const double      lift = 0.2, plane = 1.25;


  ContactSettings
  contact_settings(const ContactSettings::Method method)
  {
    ContactSettings settings;
    settings.method = method;
    settings.sides  = {"top"};
    return settings;
  }


  Vector<double>
  lifted_state(const SceneFixture &scene, const double noise)
  {
    const auto                      &spaces = scene.system->spaces();
    Vector<double>                   state(spaces.n_dofs());
    std::mt19937                     rng(5);
    std::uniform_real_distribution<> u(-1., 1.);
    for (unsigned int i = 0; i < spaces.n_dofs(); ++i)
      state(i) = i < spaces.n_u_dofs() ? (i % 2 == 1 ? lift : 0.) + noise * u(rng)
                                       : scene.material.mu_0() + 10. * noise * u(rng);
    return state;
  }


  bool
  report(const std::string &what, const bool ok)
  {
    std::cout << "  " << what << ": " << (ok ? "yes" : "no  FAIL") << std::endl;
    return ok;
  }


  bool
  check_penalty_force()
  {
    SceneFixture scene("symmetric", grid_below_plane);
    auto        &system = *scene.system;
    const double dt     = 0.05;
    std::cout << "penalty contact force" << std::endl;

    system.set_contact(contact_settings(ContactSettings::Method::penalty));
    const Vector<double> rest = lifted_state(scene, 0.);
    Vector<double>       at_rest(rest);
    for (unsigned int i = 1; i < system.spaces().n_u_dofs(); i += 2)
      at_rest(i) = 0.;
    const auto [n_rest, penetration_rest] = system.contact_state(at_rest);
    bool ok = report("at rest no point touches", n_rest == 0 && penetration_rest == 0.);

    const auto [n_active, penetration] = system.contact_state(rest);
    system.assemble(rest, dt, false);
    const Vector<double> with_contact = system.residual();
    system.set_contact(contact_settings(ContactSettings::Method::none));
    system.assemble(rest, dt, false);
    double force = 0.;
    for (unsigned int i = 1; i < system.spaces().n_u_dofs(); i += 2)
      force += with_contact(i) - system.residual()(i);

    using Layout         = GelMPM::PropertyLayout<2>;
    const double beta    = 1000. * scene.material.shear_modulus() / system.spaces().h_u();
    double       sum     = 0.;
    unsigned int n_top   = 0;
    double       deepest = 0.;
    for (const auto &particle : scene.particles)
      {
        const auto   props = particle.get_properties();
        const double g     = particle.get_location()[1] + lift - plane;
        // Only the free piece touches: 'top' (index 3); its corners belong to prescribed pieces.
        if (GelMPM::piece_of(props) != 3 || g <= 0.)
          continue;
        sum += props[Layout::measure_n] * beta * g;
        deepest = std::max(deepest, g);
        ++n_top;
      }
    std::cout << "  " << n_top << " surface points penetrate, by up to " << deepest << std::endl;
    ok &= report("contact_state counts them", n_active == n_top && n_top > 0);
    ok &= report("and its penetration is theirs (1e-12)", std::abs(penetration - deepest) < 1e-12);
    ok &= report("contact force = sum A_s beta_c g_s (1e-10 relative)",
                 std::abs(force - sum) < 1e-10 * sum);
    return ok;
  }


  /** The y-residual summed over the displacement functions: the force on the body. */
  double
  vertical_force(const GelMPM::MixedSystem<2> &system)
  {
    double force = 0.;
    for (unsigned int i = 1; i < system.spaces().n_u_dofs(); i += 2)
      force += system.residual()(i);
    return force;
  }


  bool
  check_held_rigid_contact()
  {
    SceneFixture scene("symmetric", grid_below_plane);
    auto        &system = *scene.system;
    const double dt     = 0.05;
    std::cout << "rigid obstacle, active set held (Nitsche) or followed (penalty)" << std::endl;
    std::vector<GelMPM::Obstacle<2>> obstacles = {
      GelMPM::Obstacle<2>::grid_side("lid", 1, plane, 1.)};
    const Vector<double> lifted = lifted_state(scene, 0.);
    Vector<double>       at_rest(lifted);
    for (unsigned int i = 1; i < system.spaces().n_u_dofs(); i += 2)
      at_rest(i) = 0.;
    system.set_contact(contact_settings(ContactSettings::Method::none));
    system.assemble(lifted, dt, false);
    const double free_lifted = vertical_force(system);
    system.assemble(at_rest, dt, false);
    const double free_at_rest = vertical_force(system);
    bool         ok           = true;
    for (const auto method : {ContactSettings::Method::nitsche, ContactSettings::Method::penalty})
      {
        const bool      held     = method == ContactSettings::Method::nitsche;
        ContactSettings settings = contact_settings(method);
        settings.sides.clear();
        settings.obstacles = {"lid"};
        system.set_contact(settings, obstacles);
        std::cout << (held ? " Nitsche" : " penalty") << std::endl;
        system.assemble(lifted, dt, false);
        const double followed     = vertical_force(system) - free_lifted;
        const auto [n_active, _g] = system.contact_state(lifted);
        system.freeze_switches(at_rest);
        system.assemble(lifted, dt, false);
        const double lifted_after_rest = vertical_force(system) - free_lifted;
        const auto   changed           = system.freeze_switches(lifted, false);
        std::cout << "  " << n_active << " points in contact at the lifted state, " << changed
                  << " switches changed against those held at rest" << std::endl;
        if (held)
          {
            ok &= report("held at rest, the lifted state has no contact force (1e-12)",
                         std::abs(lifted_after_rest) <= 1e-12 * std::abs(followed));
            ok &= report("each point in contact is a changed switch",
                         changed == n_active && n_active > 0);
          }
        else
          ok &= report("not held: the lifted state's force is the iterate's, no switch counted",
                       std::abs(lifted_after_rest - followed) <= 1e-12 * std::abs(followed) &&
                         changed == 0 && n_active > 0);
        system.release_switches();
        system.assemble(lifted, dt, false);
        ok &= report("released, the lifted state's contact force is the iterate's (1e-12)",
                     std::abs(vertical_force(system) - free_lifted - followed) <=
                       1e-12 * std::abs(followed));
        system.assemble(at_rest, dt, false);
        const double at_rest_followed = vertical_force(system) - free_at_rest;
        system.freeze_switches(lifted);
        system.assemble(at_rest, dt, false);
        const double at_rest_after_lift = vertical_force(system) - free_at_rest;
        if (held)
          ok &= report("held in contact, the state at rest has a contact force; followed, none",
                       at_rest_followed == 0. && at_rest_after_lift != 0.);
        else
          ok &= report("not held, the state at rest has no contact force",
                       at_rest_followed == 0. && at_rest_after_lift == 0.);
        system.release_switches();
      }
    return ok;
  }


  bool
  check_tangent(const ContactSettings::Method method, const std::string &name)
  {
    SceneFixture scene("symmetric", grid_below_plane);
    auto        &system = *scene.system;
    system.set_contact(contact_settings(method));
    const unsigned int   n     = system.spaces().n_dofs();
    const Vector<double> state = lifted_state(scene, 2e-3);
    const double         dt    = 0.05;
    std::cout << name << " contact tangent" << std::endl;

    system.assemble(state, dt, true);
    FullMatrix<double> K(n, n);
    for (unsigned int i = 0; i < n; ++i)
      for (unsigned int j = 0; j < n; ++j)
        K(i, j) = system.matrix().el(i, j);
    double error = 0., largest = 0., asymmetry = 0.;
    for (unsigned int j = 0; j < n; ++j)
      {
        const double   h = j < system.spaces().n_u_dofs() ? 1e-7 : 1e-6;
        Vector<double> plus(state), minus(state);
        plus(j) += h;
        minus(j) -= h;
        system.assemble(plus, dt, false);
        const Vector<double> r_plus = system.residual();
        system.assemble(minus, dt, false);
        for (unsigned int i = 0; i < n; ++i)
          {
            const double fd = (r_plus(i) - system.residual()(i)) / (2. * h);
            error           = std::max(error, std::abs(K(i, j) - fd));
            largest         = std::max(largest, std::abs(K(i, j)));
            asymmetry       = std::max(asymmetry, std::abs(K(i, j) - K(j, i)));
          }
      }
    const auto [n_active, penetration] = system.contact_state(state);
    std::cout << "  " << n_active << " points in contact" << std::endl;
    bool ok = report("|K - K_fd| / max|K| < 1e-6", error <= 1e-6 * largest);
    ok &= report("symmetric to 1e-12", asymmetry <= 1e-12 * largest);
    return ok;
  }
} // namespace


int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  bool                             ok = check_penalty_force();
  ok &= check_held_rigid_contact();
  ok &= check_tangent(ContactSettings::Method::penalty, "penalty");
  ok &= check_tangent(ContactSettings::Method::nitsche, "Nitsche");
  std::cout << (ok ? "contact checks passed" : "CONTACT CHECKS FAILED") << std::endl;
  return ok ? 0 : 1;
}
