#include <gelmpm/assembly/axisymmetric_terms.h>
#include <gelmpm/assembly/displacement_nitsche.h>
#include <gelmpm/assembly/self_contact.h>
#include <gelmpm/core/input_error.h>
#include <gelmpm/core/non_physical_state.h>
#include <gelmpm/geometry/surface_geometry.h>
#include <gelmpm/particles/property_layout.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace GelMPM
{
  using dealii::Point;
  using dealii::Tensor;


  namespace
  {
    /**
     * How far beyond its ends (relative to its length) a point still projects onto a segment: a
     * point that projects onto the common end of two segments of a straight surface is on both,
     * whatever the round-off of xi (both put the same force on that end; the deepest is taken).
     */
    constexpr double end_tolerance = 1e-9;
  } // namespace


  template <int dim>
  std::vector<bool>
  self_contact_pieces(const SelfContactSettings     &settings,
                      const BoundaryConditions<dim> &conditions)
  {
    std::vector<bool> chosen(conditions.n_pieces(), false);
    for (unsigned int p = 0; p < conditions.n_pieces(); ++p)
      chosen[p] = settings.pieces.empty() && !conditions.piece(p).displacement_prescribed();
    for (const auto &name : settings.pieces)
      {
        unsigned int p = 0;
        while (p < conditions.n_pieces() && conditions.piece(p).name != name)
          ++p;
        require(p < conditions.n_pieces(),
                "Contact/Self contact/Pieces",
                "names '" + name + "', which is not a piece of 'Boundary conditions/Pieces'",
                "list pieces of 'Boundary conditions/Pieces', or leave it empty (every free "
                "piece)");
        require(!conditions.piece(p).displacement_prescribed(),
                "Contact/Self contact/Pieces",
                "names '" + name + "', whose displacement is prescribed",
                "list pieces with a free displacement only");
        chosen[p] = true;
      }
    return chosen;
  }


  template <int dim>
  void
  SelfContactAssembler<dim>::set_settings(const SelfContactSettings &self_contact)
  {
    settings = self_contact;
    chosen   = self_contact_pieces(settings, this->boundary_conditions);
  }


  template <int dim>
  double
  SelfContactAssembler<dim>::penalty(const PointRecord<dim> &r) const
  {
    return settings.penalty * r.gel->shear_modulus() / this->spaces.h_u(r.level);
  }


  template <int dim>
  bool
  SelfContactAssembler<dim>::tangent_planes() const
  {
    return dim == 3 || settings.tangent_planes;
  }


  template <int dim>
  double
  SelfContactAssembler<dim>::spacing(const PointRecord<dim> &r) const
  {
    // An axisymmetric measure is revolved: 2 pi r_n times the meridian's length.
    const double revolved =
      (r.axisymmetric() && r.x[0] > 0.) ? 2. * dealii::numbers::PI * r.x[0] : 1.;
    return std::pow(r.measure / revolved, 1. / std::max(dim - 1, 1));
  }


  template <int dim>
  unsigned int
  SelfContactAssembler<dim>::n_pairs() const
  {
    return pairs_.size();
  }


  template <int dim>
  Point<dim>
  SelfContactAssembler<dim>::current_position(const unsigned int            p,
                                              const dealii::Vector<double> &solution) const
  {
    const Sample &sample = samples_[p];
    Point<dim>    x      = sample.x;
    for (unsigned int a = 0; a < sample.dofs.size(); ++a)
      for (unsigned int d = 0; d < dim; ++d)
        x[d] += sample.N[a] * solution(dim * sample.dofs[a] + d);
    return x;
  }


  template <int dim>
  PairGap<dim>
  SelfContactAssembler<dim>::pair_gap(const Pair                   &pair,
                                      const dealii::Vector<double> *solution) const
  {
    const auto x = [&](const unsigned int p) {
      return solution != nullptr ? current_position(p, *solution) : samples_[p].x;
    };
    if constexpr (dim == 2)
      if (!tangent_planes())
        return point_segment_gap(x(pair.point), x(pair.a), x(pair.b));
    return point_plane_gap(x(pair.point), x(pair.a), samples_[pair.a].normal);
  }


  template <int dim>
  bool
  SelfContactAssembler<dim>::projects_onto(const Pair &pair, const PairGap<dim> &gap) const
  {
    if (!tangent_planes())
      return gap.xi >= -end_tolerance && gap.xi <= 1. + end_tolerance;
    return gap.xi <= samples_[pair.a].spacing;
  }


  template <int dim>
  std::vector<typename SelfContactAssembler<dim>::Sample>
  SelfContactAssembler<dim>::gather_samples(const PointCache<dim> &cache) const
  {
    using Layout = PropertyLayout<dim>;
    // Flat rows of doubles for the all-gather: id, X_0, N_0 A_0, x, N_n, A_n, beta_s, spacing, the
    // u cell, the number of functions, their DoFs and their values, the index of the record.
    std::vector<std::vector<double>> rows;
    const auto                      &points = cache.points();
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        const auto &r = points[p];
        if (r.kind == PointKind::volume || r.piece < 0 || !chosen[r.piece])
          continue;
        const auto          particle   = cache.particle(p);
        const auto          properties = particle->get_properties();
        const auto         &block      = cache.blocks()[r.block];
        const auto         &dofs       = cache.u_dofs(block);
        const double       *N          = cache.u_values_at(r);
        std::vector<double> row{static_cast<double>(particle->get_id())};
        for (unsigned int d = 0; d < dim; ++d)
          row.push_back(r.X0[d]);
        for (unsigned int d = 0; d < dim; ++d)
          row.push_back(properties[Layout::normal_area_0 + d]);
        for (unsigned int d = 0; d < dim; ++d)
          row.push_back(r.x[d] + r.edge_offset[d]);
        for (unsigned int d = 0; d < dim; ++d)
          row.push_back(r.normal[d]);
        row.insert(row.end(),
                   {r.measure,
                    penalty(r),
                    spacing(r),
                    static_cast<double>(block.u_cell),
                    static_cast<double>(dofs.size())});
        row.insert(row.end(), dofs.begin(), dofs.end());
        row.insert(row.end(), N, N + dofs.size());
        row.push_back(p);
        rows.push_back(std::move(row));
      }
    const MPI_Comm communicator = cache.get_communicator();
    const auto     unpack       = [](const std::vector<double> &row, const bool here) {
      Sample       s;
      unsigned int k = 0;
      s.id           = row[k++];
      for (unsigned int d = 0; d < dim; ++d)
        s.X0[d] = row[k++];
      for (unsigned int d = 0; d < dim; ++d)
        s.normal_area_0[d] = row[k++];
      for (unsigned int d = 0; d < dim; ++d)
        s.x[d] = row[k++];
      for (unsigned int d = 0; d < dim; ++d)
        s.normal[d] = row[k++];
      s.measure            = row[k++];
      s.penalty            = row[k++];
      s.spacing            = row[k++];
      s.u_cell             = static_cast<unsigned int>(row[k++]);
      const unsigned int n = static_cast<unsigned int>(row[k++]);
      s.dofs.assign(row.begin() + k, row.begin() + k + n);
      s.N.assign(row.begin() + k + n, row.begin() + k + 2 * n);
      s.record = static_cast<unsigned int>(row[k + 2 * n]);
      s.here   = here;
      return s;
    };
    std::vector<Sample> samples;
    if (dealii::Utilities::MPI::n_mpi_processes(communicator) == 1)
      for (const auto &row : rows)
        samples.push_back(unpack(row, true));
    else
      {
        const unsigned int rank = dealii::Utilities::MPI::this_mpi_process(communicator);
        const auto         all  = dealii::Utilities::MPI::all_gather(communicator, rows);
        for (unsigned int from = 0; from < all.size(); ++from)
          for (const auto &row : all[from])
            samples.push_back(unpack(row, from == rank));
      }
    // The same order on every partition (one rank included): the pairs, the ties between the
    // segments a point projects on and so the active sets follow it.
    std::sort(samples.begin(), samples.end(), [](const Sample &a, const Sample &b) {
      return a.id < b.id;
    });
    return samples;
  }


  template <int dim>
  std::vector<typename SelfContactAssembler<dim>::Pair>
  SelfContactAssembler<dim>::find_pairs(const dealii::Vector<double> *solution) const
  {
    return tangent_planes() ? find_point_pairs(solution) : find_segment_pairs(solution);
  }


  template <int dim>
  std::vector<typename SelfContactAssembler<dim>::Pair>
  SelfContactAssembler<dim>::find_segment_pairs(const dealii::Vector<double> *solution) const
  {
    // tangent_planes() holds in 3D: only a 2D scene gets here.
    if constexpr (dim == 2)
      {
        // In cells of 'Background grid/Cells' at every level: the motion within a step and
        // the spacing of surface points, which refinement does not shorten.
        const double                               h = this->spaces.h_u(0);
        std::vector<SurfaceGeometry::SurfacePoint> surface;
        for (unsigned int p = 0; p < samples_.size(); ++p)
          {
            SurfaceGeometry::SurfacePoint s;
            s.X_0      = samples_[p].X0;
            s.normal_0 = samples_[p].normal_area_0;
            s.x        = solution != nullptr ? current_position(p, *solution) : samples_[p].x;
            s.index    = p;
            surface.push_back(s);
          }
        // As the observables order a piece: surface points are at most h apart (a cell of the
        // unrefined grid; refined cells hold more of them).
        const auto line = SurfaceGeometry::order_along_surface(std::move(surface), 2. * h);

        // The segments (i, i + 1) of every curve, the closing one of a closed curve, and the curve
        // of every point.
        std::vector<std::array<unsigned int, 2>> segments;
        std::vector<unsigned int>                curve_of(line.points.size());
        for (unsigned int c = 0; c < line.n_curves(); ++c)
          {
            const unsigned int begin = line.curve_begin[c], end = line.curve_begin[c + 1];
            for (unsigned int i = begin; i < end; ++i)
              {
                curve_of[i] = c;
                if (i + 1 < end)
                  segments.push_back({{i, i + 1}});
              }
            if (line.closed[c] && end - begin >= 3)
              segments.push_back({{end - 1, begin}});
          }
        const auto arc_length =
          [&line](const unsigned int i, const unsigned int j, const unsigned c) {
            const double s = std::abs(line.s_0[i] - line.s_0[j]);
            return line.closed[c] ? std::min(s, line.length_0[c] - s) : s;
          };

        // At the end of a step every point behind the surface counts, however deep.
        const double search     = settings.search_distance * h,
                     depth      = solution == nullptr ? settings.largest_depth * h
                                                      : std::numeric_limits<double>::infinity(),
                     separation = settings.minimum_arc_length * h;
        std::vector<Pair> found;
        for (unsigned int i = 0; i < line.points.size(); ++i)
          {
            const Point<2> &x_s    = line.points[i].x;
            const auto     &normal = samples_[line.points[i].index].normal;
            for (const auto &[ja, jb] : segments)
              {
                const Point<2> &x_a = line.points[ja].x, &x_b = line.points[jb].x;
                // Bounding boxes first: most segments are far away.
                bool far = false;
                for (unsigned int d = 0; d < 2 && !far; ++d)
                  far = x_s[d] < std::min(x_a[d], x_b[d]) - search ||
                        x_s[d] > std::max(x_a[d], x_b[d]) + search;
                if (far)
                  continue;
                const unsigned int c = curve_of[ja];
                if (curve_of[i] == c &&
                    (arc_length(i, ja, c) < separation || arc_length(i, jb, c) < separation))
                  continue;
                const Tensor<1, 2> e = x_b - x_a;
                const double       L = e.norm();
                if (L == 0.)
                  continue;
                const Tensor<1, 2> n({-e[1] / L, e[0] / L});
                const double       g        = (x_s - x_a) * n;
                const double       xi       = std::clamp((x_s - x_a) * e / (L * L), 0., 1.);
                const double       distance = (x_s - (x_a + xi * e)).norm();
                if (distance <= search && g >= -depth && normal * n < 0.)
                  found.push_back(
                    {line.points[i].index, line.points[ja].index, line.points[jb].index});
              }
          }
        return found;
      }
    else
      {
        (void)solution;
        return {};
      }
  }


  template <int dim>
  std::vector<typename SelfContactAssembler<dim>::Pair>
  SelfContactAssembler<dim>::find_point_pairs(const dealii::Vector<double> *solution) const
  {
    // In cells of the grid as given, as the 2D segments'.
    const double h          = this->spaces.h_u(0);
    const double search     = settings.search_distance * h,
                 depth      = solution == nullptr ? settings.largest_depth * h
                                                  : std::numeric_limits<double>::infinity(),
                 separation = settings.minimum_arc_length * h;
    std::vector<Point<dim>> x(samples_.size());
    for (unsigned int p = 0; p < samples_.size(); ++p)
      x[p] = solution != nullptr ? current_position(p, *solution) : samples_[p].x;
    const auto        near = points_within(x, search);
    std::vector<Pair> found;
    for (unsigned int s = 0; s < x.size(); ++s)
      {
        const Sample        &point = samples_[s];
        const Tensor<1, dim> N_0   = point.normal_area_0 / point.normal_area_0.norm();
        for (const unsigned int m : near[s])
          {
            // Facing: turned from each other by more than 120 degrees. A point of a side next
            // to an edge of the other face is turned by 90 degrees, where round-off of the
            // fitted normals decides the sign of N_s . N_m.
            const Sample &other = samples_[m];
            if (point.normal * other.normal >= -0.5)
              continue;
            // Its own face near it in the initial configuration (the flanks next to a fold's
            // tip): as the 2D arc length, the straight distance on one face (not turned from
            // each other by 120 degrees there).
            if ((point.X0 - other.X0).norm() < separation &&
                N_0 * other.normal_area_0 >= -0.5 * other.normal_area_0.norm())
              continue;
            if ((x[s] - x[m]) * other.normal >= -depth)
              found.push_back({s, m, m});
          }
      }
    return found;
  }


  template <int dim>
  void
  SelfContactAssembler<dim>::add_cell_couplings(
    const PointCache<dim>                              &cache,
    std::vector<std::pair<unsigned int, unsigned int>> &pairs) const
  {
    samples_ = gather_samples(cache);
    pairs_   = find_pairs();
    held_.clear();
    // The pattern couples the unknowns of a block (a leaf) with each other only: two points of
    // different blocks need their cells coupled, also when both blocks are leaves of one cell of
    // a refined grid (the pair (c, c) then couples all of the cell's pieces). The rank that
    // assembles a pair (its point's) couples them, and writes their rows.
    for (const auto &pair : pairs_)
      if (samples_[pair.point].here)
        {
          const unsigned int nodes[3] = {pair.point, pair.a, pair.b};
          for (unsigned int k = 0; k < 3; ++k)
            for (unsigned int l = k + 1; l < 3; ++l)
              if (samples_[nodes[k]].dofs != samples_[nodes[l]].dofs)
                pairs.emplace_back(samples_[nodes[k]].u_cell, samples_[nodes[l]].u_cell);
          // A segment's end held by another rank is in no block of this one: the entries
          // among its own unknowns, which the pair writes too, need its cell coupled with itself.
          for (const unsigned int node : nodes)
            if (!samples_[node].here)
              pairs.emplace_back(samples_[node].u_cell, samples_[node].u_cell);
        }
    for (const CopyTie &tie : cache.copy_ties())
      pairs.emplace_back(tie.cell, tie.donor_cell);
  }


  template <int dim>
  unsigned int
  SelfContactAssembler<dim>::hold_active_pairs(const PointCache<dim>        &cache,
                                               const dealii::Vector<double> &solution,
                                               const bool                    hold) const
  {
    std::vector<PairGap<dim>> gaps;
    const auto active = active_pairs(solution, gaps, false, tractions(cache, solution));
    // Per group of a point's pairs, its active pair at @p solution or -1.
    std::vector<int> now;
    for (unsigned int k = 0, a = 0; k < pairs_.size();)
      {
        const unsigned int point = pairs_[k].point;
        int                which = -1;
        for (; k < pairs_.size() && pairs_[k].point == point; ++k)
          if (a < active.size() && active[a] == static_cast<int>(k))
            {
              which = k;
              ++a;
            }
        now.push_back(which);
      }
    // Counted by the rank of the point: the callers sum over the ranks.
    unsigned int changed = 0;
    if (!held_.empty())
      for (unsigned int k = 0, g = 0; k < pairs_.size(); ++g)
        {
          const unsigned int point = pairs_[k].point;
          changed += samples_[point].here && now[g] != held_[g];
          while (k < pairs_.size() && pairs_[k].point == point)
            ++k;
        }
    if (hold)
      held_ = std::move(now);
    return changed;
  }


  template <int dim>
  void
  SelfContactAssembler<dim>::assemble_copy_ties(const PointCache<dim>        &cache,
                                                const dealii::Vector<double> &solution,
                                                const bool                    with_matrix,
                                                std::vector<AssemblyCopy>    &copies) const
  {
    // kappa/2 |u_c - sum_j E_j u_j|^2 per component: a = (1, -E_1, ...), R = kappa a (a . u),
    // K = kappa a (x) a.
    for (const CopyTie &tie : cache.copy_ties())
      for (unsigned int i = 0; i < dim; ++i)
        {
          std::vector<std::pair<unsigned int, double>> a = {{dim * tie.copy + i, 1.}};
          for (const auto &[dof, E] : tie.donors)
            a.emplace_back(dim * dof + i, -E);
          double misfit = 0.;
          for (const auto &[row, weight] : a)
            misfit += weight * solution(row);
          AssemblyCopy copy;
          for (const auto &[row, weight] : a)
            copy.dofs.push_back(row);
          copy.residual.reinit(a.size());
          if (with_matrix)
            copy.matrix.reinit(a.size(), a.size());
          for (unsigned int k = 0; k < a.size(); ++k)
            {
              copy.residual(k) = tie.stiffness * a[k].second * misfit;
              if (with_matrix)
                for (unsigned int l = 0; l < a.size(); ++l)
                  copy.matrix(k, l) = tie.stiffness * a[k].second * a[l].second;
            }
          copies.push_back(std::move(copy));
        }
  }


  template <int dim>
  unsigned int
  SelfContactAssembler<dim>::unseen_contacts(const PointCache<dim> &,
                                             const dealii::Vector<double> &solution) const
  {
    std::vector<PairGap<dim>> gaps;
    std::vector<bool>         seen(samples_.size(), false);
    for (const int k : active_pairs(solution, gaps, false))
      seen[pairs_[k].point] = true;
    // Passed through: behind the surface at the end, and at the start in front of it or no
    // deeper than a pair may start (a point of one face lies behind the other face of a thin
    // body at both ends of the step).
    const double      depth = settings.largest_depth * this->spaces.h_u(0);
    std::vector<bool> behind(samples_.size(), false);
    for (const Pair &pair : find_pairs(&solution))
      {
        const auto gap = pair_gap(pair, &solution);
        if (gap.g < 0. && projects_onto(pair, gap) && pair_gap(pair, nullptr).g >= -depth)
          behind[pair.point] = true;
      }
    unsigned int n = 0;
    for (unsigned int p = 0; p < behind.size(); ++p)
      n += behind[p] && !seen[p];
    return n;
  }


  template <int dim>
  std::vector<int>
  SelfContactAssembler<dim>::active_pairs(const dealii::Vector<double>      &solution,
                                          std::vector<PairGap<dim>>         &gaps,
                                          const bool                         use_held,
                                          const std::vector<Tensor<1, dim>> &tractions) const
  {
    gaps.resize(pairs_.size());
    std::vector<int> active;
    // The pairs of a point follow each other; its active pair is the deepest it lies behind
    // (3D: the nearest point whose tangent plane it lies behind), or the one held
    // (hold_active_pairs()).
    for (unsigned int k = 0, group = 0; k < pairs_.size(); ++group)
      {
        const unsigned int point   = pairs_[k].point;
        int                deepest = -1;
        // A point on the common end of two segments of a straight face lies equally deep
        // behind both: which one round-off makes the deeper must not switch the active pair
        // (measured: 17 of 36 points of two pressed blocks switched between two Newton
        // iterates, a switch update more on one rank than on two). A deeper pair must be so
        // by more than round-off of the positions.
        const double tie = 1e-9 * this->spaces.h_u(0);
        for (; k < pairs_.size() && pairs_[k].point == point; ++k)
          {
            gaps[k] = pair_gap(pairs_[k], &solution);
            // Nitsche's active set: the augmented normal traction sigma_n - beta_s g > 0 (a
            // compressed point may lie in front of the segment); the penalty's: g < 0.
            const bool touches =
              tractions.empty()
                ? gaps[k].g < 0.
                : samples_[point].penalty * gaps[k].g - gaps[k].normal * tractions[point] < 0.;
            const auto closer = [&](const PairGap<dim> &a, const PairGap<dim> &b) {
              return tangent_planes() ? a.xi < b.xi - tie : a.g < b.g - tie;
            };
            if (touches && projects_onto(pairs_[k], gaps[k]) &&
                (deepest < 0 || closer(gaps[k], gaps[deepest])))
              deepest = k;
          }
        if (use_held && !held_.empty())
          deepest = held_[group];
        if (deepest >= 0)
          active.push_back(deepest);
      }
    return active;
  }


  template <int dim>
  void
  SelfContactAssembler<dim>::assemble_beyond_blocks(const PointCache<dim>        &cache,
                                                    const dealii::Vector<double> &solution,
                                                    const double /*dt*/,
                                                    const bool                 with_matrix,
                                                    std::vector<AssemblyCopy> &copies) const
  {
    assemble_copy_ties(cache, solution, with_matrix, copies);
    std::vector<PairGap<dim>> gaps;
    const auto active = active_pairs(solution, gaps, true, tractions(cache, solution));
    // An iterate with a point farther behind a segment than a pair may start: not a state the
    // penalty leaves (sigma_n / beta_s) but a Newton update that overshot, whose forces would
    // throw the next one farther; the line search damps it as it damps a J <= 1.
    const double depth = settings.largest_depth * this->spaces.h_u(0);
    for (const int k : active)
      if (-gaps[k].g > depth)
        throw NonPhysicalState("a surface point of the self-contact lies " +
                               std::to_string(-gaps[k].g) +
                               " behind the surface, beyond 'Contact/Self contact/Largest depth'");
    // Every rank knows every pair; the point's rank adds it (the residual is summed over the
    // ranks).
    for (const int k : active)
      if (samples_[pairs_[k].point].here)
        copies.push_back(settings.method == SelfContactSettings::Method::nitsche
                           ? nitsche_pair(cache, solution, pairs_[k], gaps[k], with_matrix)
                           : penalty_pair(pairs_[k], gaps[k], with_matrix));
  }


  template <int dim>
  AssemblyCopy
  SelfContactAssembler<dim>::penalty_pair(const Pair         &pair,
                                          const PairGap<dim> &gap,
                                          const bool          with_matrix) const
  {
    // W = A beta g^2 / 2: dW = A beta g dg, d2W = A beta (dg (x) dg + g d2g).
    const double       scale    = samples_[pair.point].measure * samples_[pair.point].penalty;
    const unsigned int nodes[3] = {pair.point, pair.a, pair.b};
    const std::vector<unsigned int> *dofs[3];
    const double                    *N[3];
    AssemblyCopy                     copy;
    for (unsigned int m = 0; m < 3; ++m)
      {
        dofs[m] = &samples_[nodes[m]].dofs;
        N[m]    = samples_[nodes[m]].N.data();
        for (const unsigned int i : *dofs[m])
          for (unsigned int d = 0; d < dim; ++d)
            copy.dofs.push_back(dim * i + d);
      }
    internal::sort_unique(copy.dofs);
    const auto local = [&copy](const unsigned int global) {
      return internal::local_index(copy.dofs, global);
    };
    copy.residual.reinit(copy.dofs.size());
    if (with_matrix)
      copy.matrix.reinit(copy.dofs.size(), copy.dofs.size());
    for (unsigned int m = 0; m < 3; ++m)
      for (unsigned int a = 0; a < dofs[m]->size(); ++a)
        for (unsigned int i = 0; i < dim; ++i)
          {
            const unsigned int row = local(dim * (*dofs[m])[a] + i);
            copy.residual(row) += scale * gap.g * gap.gradient[dim * m + i] * N[m][a];
            if (!with_matrix)
              continue;
            for (unsigned int l = 0; l < 3; ++l)
              for (unsigned int c = 0; c < dofs[l]->size(); ++c)
                for (unsigned int j = 0; j < dim; ++j)
                  copy.matrix(row, local(dim * (*dofs[l])[c] + j)) +=
                    scale * N[m][a] * N[l][c] *
                    (gap.gradient[dim * m + i] * gap.gradient[dim * l + j] +
                     gap.g * gap.hessian[dim * m + i][dim * l + j]);
          }
    return copy;
  }


  template <int dim>
  std::vector<Tensor<1, dim>>
  SelfContactAssembler<dim>::tractions(const PointCache<dim>        &cache,
                                       const dealii::Vector<double> &solution) const
  {
    if (settings.method != SelfContactSettings::Method::nitsche)
      return {};
    std::vector<Tensor<1, dim>> t(samples_.size());
    AssemblyScratch<dim>        s;
    for (unsigned int k = 0; k < pairs_.size(); ++k)
      if ((k == 0 || pairs_[k].point != pairs_[k - 1].point) && samples_[pairs_[k].point].here)
        {
          const auto &record = cache.points()[samples_[pairs_[k].point].record];
          s.gather_block_coefficients(cache.blocks()[record.block], cache, this->spaces, solution);
          s.evaluate_point_fields(record, cache);
          t[pairs_[k].point] =
            point_state(record, s.delta_F, s.du_at_point, s.mu_at_point, false).P_n * record.normal;
        }
    // Each point's rank evaluates its traction; every rank needs all of them for the same
    // active sets and statistics (the positions it has whole).
    const MPI_Comm communicator = cache.get_communicator();
    if (dealii::Utilities::MPI::n_mpi_processes(communicator) > 1)
      {
        std::vector<double> flat(dim * t.size());
        for (unsigned int p = 0; p < t.size(); ++p)
          for (unsigned int d = 0; d < dim; ++d)
            flat[dim * p + d] = t[p][d];
        dealii::Utilities::MPI::sum(flat, communicator, flat);
        for (unsigned int p = 0; p < t.size(); ++p)
          for (unsigned int d = 0; d < dim; ++d)
            t[p][d] = flat[dim * p + d];
      }
    return t;
  }


  template <int dim>
  AssemblyCopy
  SelfContactAssembler<dim>::nitsche_pair(const PointCache<dim>        &cache,
                                          const dealii::Vector<double> &solution,
                                          const Pair                   &pair,
                                          const PairGap<dim>           &gap,
                                          const bool                    with_matrix) const
  {
    // With X = (x_s, x_a, x_b), sigma = n(X) . t(y) (t = P_n N_n, y the point's displacement
    // and chemical-potential unknowns) and theta the variant's symmetry:
    //   R = A/2 [(beta g - sigma) dg - theta g dsigma],
    //   K = A/2 [beta dg dg - dg dsigma - theta dsigma dg + (beta g - sigma) d2g - theta g
    //   d2sigma], d2sigma = dn^T dt + dt^T dn + t . d2n + n . d2t,
    // each derivative in X mapped to the unknowns by X's shape values (B). dt and n . d2t come
    // from add_displacement_nitsche() with Pi = 0 and beta = 0 (its symmetry term alone), which
    // holds the gel's tangent and its third derivative, axisymmetric too.
    const Sample           &sample = samples_[pair.point];
    const PointRecord<dim> &record = cache.points()[sample.record];
    const PointBlock       &block  = cache.blocks()[record.block];
    AssemblyScratch<dim>    s;
    s.gather_block_coefficients(block, cache, this->spaces, solution);
    s.evaluate_point_fields(record, cache);
    const unsigned int        n_y     = dim * s.n_u + s.n_mu;
    const auto               &u_dofs  = cache.u_dofs(block);
    const auto               &mu_dofs = cache.mu_dofs(block);
    std::vector<unsigned int> y_dofs(n_y);
    for (unsigned int a = 0; a < s.n_u; ++a)
      for (unsigned int k = 0; k < dim; ++k)
        y_dofs[dim * a + k] = dim * u_dofs[a] + k;
    for (unsigned int b = 0; b < s.n_mu; ++b)
      y_dofs[s.mu0() + b] = this->spaces.n_u_dofs() + mu_dofs[b];

    AssemblyCopy       copy;
    const unsigned int nodes[3] = {pair.point, pair.a, pair.b};
    copy.dofs.assign(y_dofs.begin(), y_dofs.end());
    for (unsigned int m = 1; m < 3; ++m)
      for (const unsigned int i : samples_[nodes[m]].dofs)
        for (unsigned int d = 0; d < dim; ++d)
          copy.dofs.push_back(dim * i + d);
    internal::sort_unique(copy.dofs);
    const auto local = [&copy](const unsigned int global) {
      return internal::local_index(copy.dofs, global);
    };
    const unsigned int n = copy.dofs.size();

    constexpr unsigned int     n_X = 3 * dim;
    dealii::FullMatrix<double> B(n_X, n), T(dim, n);
    for (unsigned int m = 0; m < 3; ++m)
      {
        const Sample &node = samples_[nodes[m]];
        for (unsigned int a = 0; a < node.dofs.size(); ++a)
          for (unsigned int i = 0; i < dim; ++i)
            B(dim * m + i, local(dim * node.dofs[a] + i)) += node.N[a];
      }
    PointRecord<dim> unit = record;
    unit.measure          = 1.;
    const double theta    = this->nitsche.symmetry;
    for (unsigned int k = 0; k < dim; ++k)
      {
        // The symmetry term with the violation e_k: its residual is -dt_k/dy.
        AssemblyCopy traction_k;
        traction_k.residual.reinit(n_y);
        Tensor<1, dim> e;
        e[k] = 1.;
        add_displacement_nitsche(unit,
                                 Tensor<2, dim>(),
                                 e,
                                 0.,
                                 1.,
                                 false,
                                 s,
                                 traction_k,
                                 this->tangent.reference_nitsche);
        for (unsigned int j = 0; j < n_y; ++j)
          T(k, local(y_dofs[j])) = -traction_k.residual(j);
      }
    const Tensor<1, dim> t =
      point_state(record, s.delta_F, s.du_at_point, s.mu_at_point, false).P_n * record.normal;
    // The tangent plane's normal is fixed over the step; a segment's turns with its ends.
    NormalDerivatives<dim> dn;
    if (!tangent_planes())
      dn =
        normal_derivatives(current_position(pair.a, solution), current_position(pair.b, solution));
    const Tensor<1, dim> &normal = gap.normal;
    const double          g = gap.g, beta = sample.penalty, sigma = normal * t;
    const double          weight = 0.5 * record.measure;

    // dn^T t per coordinate of X, and dg, dsigma, dn B per unknown.
    double t_dn[n_X] = {};
    for (unsigned int K = 0; K < n_X; ++K)
      for (unsigned int i = 0; i < dim; ++i)
        t_dn[K] += t[i] * dn.first[i][K];
    std::vector<double>        dg(n, 0.), dsigma(n, 0.);
    dealii::FullMatrix<double> dnB(dim, n);
    for (unsigned int q = 0; q < n; ++q)
      {
        for (unsigned int K = 0; K < n_X; ++K)
          {
            dg[q] += gap.gradient[K] * B(K, q);
            dsigma[q] += t_dn[K] * B(K, q);
            for (unsigned int i = 0; i < dim; ++i)
              dnB(i, q) += dn.first[i][K] * B(K, q);
          }
        for (unsigned int i = 0; i < dim; ++i)
          dsigma[q] += normal[i] * T(i, q);
      }
    copy.residual.reinit(n);
    for (unsigned int q = 0; q < n; ++q)
      copy.residual(q) = weight * ((beta * g - sigma) * dg[q] - theta * g * dsigma[q]);
    if (!with_matrix)
      return copy;

    // H = (beta g - sigma) d2g - theta g t . d2n in X, and H B.
    double H[n_X][n_X];
    for (unsigned int K = 0; K < n_X; ++K)
      for (unsigned int L = 0; L < n_X; ++L)
        {
          double t_d2n = 0.;
          for (unsigned int i = 0; i < dim; ++i)
            t_d2n += t[i] * dn.second[i][K][L];
          H[K][L] = (beta * g - sigma) * gap.hessian[K][L] - theta * g * t_d2n;
        }
    dealii::FullMatrix<double> HB(n_X, n);
    for (unsigned int K = 0; K < n_X; ++K)
      for (unsigned int L = 0; L < n_X; ++L)
        if (H[K][L] != 0.)
          for (unsigned int r = 0; r < n; ++r)
            HB(K, r) += H[K][L] * B(L, r);
    copy.matrix.reinit(n, n);
    for (unsigned int q = 0; q < n; ++q)
      for (unsigned int r = 0; r < n; ++r)
        {
          double BHB = 0., mixed = 0.;
          for (unsigned int K = 0; K < n_X; ++K)
            BHB += B(K, q) * HB(K, r);
          for (unsigned int i = 0; i < dim; ++i)
            mixed += T(i, q) * dnB(i, r) + dnB(i, q) * T(i, r);
          copy.matrix(q, r) = weight * (beta * dg[q] * dg[r] - dg[q] * dsigma[r] -
                                        theta * dsigma[q] * dg[r] + BHB - theta * g * mixed);
        }
    // n . d2t along g n: the matrix of the symmetry term with the violation g n alone.
    AssemblyCopy third;
    third.residual.reinit(n_y);
    third.matrix.reinit(n_y, n_y);
    add_displacement_nitsche(unit,
                             Tensor<2, dim>(),
                             g * normal,
                             0.,
                             theta,
                             true,
                             s,
                             third,
                             this->tangent.reference_nitsche);
    for (unsigned int i = 0; i < n_y; ++i)
      for (unsigned int j = 0; j < n_y; ++j)
        copy.matrix(local(y_dofs[i]), local(y_dofs[j])) += weight * third.matrix(i, j);
    return copy;
  }


  template <int dim>
  typename SelfContactAssembler<dim>::State
  SelfContactAssembler<dim>::state(const PointCache<dim>        &cache,
                                   const dealii::Vector<double> &solution) const
  {
    // The same on every rank: the samples and the Newton vector are whole on each.
    State                     state;
    std::vector<PairGap<dim>> gaps;
    const auto                t = tractions(cache, solution);
    for (const int k : active_pairs(solution, gaps, true, t))
      {
        const Sample &point = samples_[pairs_[k].point];
        ++state.points;
        state.force += t.empty()
                         ? point.measure * point.penalty * -gaps[k].g
                         : 0.5 * point.measure *
                             (gaps[k].normal * t[pairs_[k].point] - point.penalty * gaps[k].g);
        state.area += 0.5 * point.measure;
        if (-gaps[k].g >= state.penetration)
          state.deepest_X0 = point.X0;
        state.penetration = std::max(state.penetration, -gaps[k].g);
      }
    return state;
  }


  template std::vector<bool>
  self_contact_pieces(const SelfContactSettings &, const BoundaryConditions<2> &);
  template std::vector<bool>
  self_contact_pieces(const SelfContactSettings &, const BoundaryConditions<3> &);
  // Point to the tangent plane of the nearest facing point; in 2D also point to segment.
  template class SelfContactAssembler<2>;
  template class SelfContactAssembler<3>;
} // namespace GelMPM
