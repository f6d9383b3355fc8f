#include <gelmpm/assembly/face_separation.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <stdexcept>
#include <unordered_map>
#include <unordered_set>

namespace GelMPM
{
  namespace Separation
  {
    /** Union-find over the points of one support. */
    struct Parts
    {
      std::vector<unsigned int> parent;

      explicit Parts(const unsigned int n)
        : parent(n)
      {
        std::iota(parent.begin(), parent.end(), 0u);
      }

      unsigned int
      root(unsigned int i)
      {
        while (parent[i] != i)
          i = parent[i] = parent[parent[i]];
        return i;
      }

      void
      join(const unsigned int a, const unsigned int b)
      {
        const unsigned int ra = root(a), rb = root(b);
        // The smaller index is the root: the parts do not depend on the order of the joins.
        if (ra != rb)
          parent[std::max(ra, rb)] = std::min(ra, rb);
      }
    };


    /** What a part of a support holds. */
    struct Part
    {
      unsigned int points            = 0;
      bool         separated_surface = false;
      double       weight            = 0.;
    };
  } // namespace Separation


  template <int dim>
  FaceSeparation<dim>::FaceSeparation(std::vector<bool> pieces,
                                      const double      along_surface,
                                      const bool        axisymmetric)
    : pieces(std::move(pieces))
    , along_surface(along_surface)
    , axisymmetric(axisymmetric)
  {}


  template <int dim>
  void
  FaceSeparation<dim>::reference_spacing(const std::vector<PointRecord<dim>>  &unsorted,
                                         const std::vector<particle_iterator> &its,
                                         std::vector<double>                  &spacing,
                                         std::vector<Tensor<1, dim>>          &normal_0) const
  {
    using Layout = PropertyLayout<dim>;
    for (unsigned int i = 0; i < unsorted.size(); ++i)
      {
        const auto   properties = its[i]->get_properties();
        const auto  &r          = unsorted[i];
        const double revolved   = (axisymmetric && r.X0[0] > 0.) ? 2. * M_PI * r.X0[0] : 1.;
        const double measure    = properties[Layout::measure_0] / revolved;
        if (r.kind == PointKind::volume)
          spacing[i] = std::pow(measure, 1. / dim);
        else
          {
            for (unsigned int d = 0; d < dim; ++d)
              normal_0[i][d] = properties[Layout::normal_area_0 + d];
            normal_0[i] /= normal_0[i].norm();
            spacing[i] = std::pow(measure, 1. / (dim - 1));
          }
      }
  }


  template <int dim>
  void
  FaceSeparation<dim>::find_neighbours(const std::vector<PointRecord<dim>>  &unsorted,
                                       const std::vector<particle_iterator> &its)
  {
    const unsigned int          n = unsorted.size();
    std::vector<double>         spacing(n);
    std::vector<Tensor<1, dim>> normal_0(n);
    reference_spacing(unsorted, its, spacing, normal_0);
    const double largest = *std::max_element(spacing.begin(), spacing.end());
    // Buckets of the largest reach in X_0: a point's neighbours lie in its own and the 3^dim - 1
    // buckets round it.
    const double reach     = 1.5 * largest;
    const auto   bucket_of = [reach](const dealii::Point<dim> &X) {
      std::array<std::int64_t, dim> b;
      for (unsigned int d = 0; d < dim; ++d)
        b[d] = static_cast<std::int64_t>(std::floor(X[d] / reach));
      return b;
    };
    const auto key = [](const std::array<std::int64_t, dim> &b) {
      std::uint64_t k = 0;
      for (unsigned int d = 0; d < dim; ++d)
        k = k * 2097152u + static_cast<std::uint64_t>(b[d] + 1048576);
      return k;
    };
    std::unordered_map<std::uint64_t, std::vector<unsigned int>> buckets;
    for (unsigned int i = 0; i < n; ++i)
      buckets[key(bucket_of(unsorted[i].X0))].push_back(i);

    // A surface point faces away from the material: nothing in front of it is its neighbour.
    const auto connected = [&](const unsigned int a, const unsigned int b) {
      const Tensor<1, dim> d = unsorted[b].X0 - unsorted[a].X0;
      if (d.norm() > 1.5 * std::max(spacing[a], spacing[b]))
        return false;
      const bool surface_a = unsorted[a].kind != PointKind::volume,
                 surface_b = unsorted[b].kind != PointKind::volume;
      if (surface_a && surface_b)
        return normal_0[a] * normal_0[b] > 0.;
      const double front = 0.25 * std::max(spacing[a], spacing[b]);
      if (surface_a)
        return d * normal_0[a] <= front;
      if (surface_b)
        return -d * normal_0[b] <= front;
      return true;
    };
    graph = PointGraph();
    graph.offsets.reserve(n + 1);
    for (unsigned int i = 0; i < n; ++i)
      {
        const auto home = bucket_of(unsorted[i].X0);
        for (unsigned int neighbour = 0; neighbour < std::pow(3, dim); ++neighbour)
          {
            auto         b    = home;
            unsigned int rest = neighbour;
            for (unsigned int d = 0; d < dim; ++d, rest /= 3)
              b[d] += static_cast<std::int64_t>(rest % 3) - 1;
            const auto bucket = buckets.find(key(b));
            if (bucket == buckets.end())
              continue;
            for (const unsigned int j : bucket->second)
              if (j != i && connected(i, j))
                graph.targets.push_back(j);
          }
        // Sorted: the parts are built in the same order whatever the buckets' order.
        std::sort(graph.targets.begin() + graph.offsets.back(), graph.targets.end());
        graph.offsets.push_back(graph.targets.size());
      }
  }


  template <int dim>
  void
  FaceSeparation<dim>::anchor_surface_points(const std::vector<PointRecord<dim>> &unsorted,
                                             std::vector<unsigned int>           &cells,
                                             std::vector<unsigned int>           &pieces) const
  {
    // A face that has come within a cell of another lies in the other's cells: evaluated there
    // it would take the other part's functions (and their copies would not reach it).
    for (unsigned int i = 0; i < unsorted.size(); ++i)
      {
        if (!separates(unsorted[i]))
          continue;
        const auto [begin, end] = graph.neighbours(i);
        bool         at_home    = false;
        unsigned int nearest    = dealii::numbers::invalid_unsigned_int;
        double       distance   = std::numeric_limits<double>::max();
        for (auto j = begin; j != end && !at_home; ++j)
          {
            if (unsorted[*j].kind != PointKind::volume)
              continue;
            at_home        = cells[*j] == cells[i] && pieces[*j] == pieces[i];
            const double d = (unsorted[*j].X0 - unsorted[i].X0).norm();
            if (d < distance)
              {
                distance = d;
                nearest  = *j;
              }
          }
        if (!at_home && nearest != dealii::numbers::invalid_unsigned_int)
          {
            cells[i]  = cells[nearest];
            pieces[i] = pieces[nearest];
          }
      }
  }


  namespace Separation
  {
    /** The points of one function's support and the parts they fall into. */
    struct SupportParts
    {
      /** The sorted points of the support, and the function's position in each one's list. */
      std::vector<unsigned int> members, position;
      Parts                     parts{0};
      /** Per root member, what its part holds; the sum of the volume points' weights. */
      std::vector<Part> part;
      double            total = 0.;

      /** The members of the part of root @p face for which @p take is true. */
      template <typename Take>
      std::vector<unsigned int>
      of_part(const unsigned int face, const Take &take)
      {
        std::vector<unsigned int> chosen;
        for (unsigned int m = 0; m < members.size(); ++m)
          if (parts.root(m) == face && take(members[m]))
            chosen.push_back(members[m]);
        return chosen;
      }
    };
  } // namespace Separation


  template <int dim>
  std::vector<std::vector<unsigned int>>
  FaceSeparation<dim>::blocks_of_separated_functions(const Grouping &g) const
  {
    // The functions of the blocks with a separated surface point, and the blocks of their
    // supports (empty for the others).
    const unsigned int n_dofs = g.u.n_dofs();
    std::vector<bool>  candidate(n_dofs, false);
    for (const PointBlock &b : g.blocks)
      for (unsigned int p = b.first; p < b.end; ++p)
        if (separates(g.points[p]))
          {
            for (const unsigned int d : g.u.cell_dofs(b.u_cell, b.u_piece))
              candidate[d] = true;
            break;
          }
    std::vector<std::vector<unsigned int>> support(n_dofs);
    for (unsigned int b = 0; b < g.blocks.size(); ++b)
      for (const unsigned int d : g.u.cell_dofs(g.blocks[b].u_cell, g.blocks[b].u_piece))
        if (candidate[d])
          support[d].push_back(b);
    return support;
  }


  template <int dim>
  std::vector<std::vector<std::pair<unsigned int, unsigned int>>>
  FaceSeparation<dim>::copies_of_points(const Grouping &g, std::vector<unsigned int> &copy_of)
  {
    const unsigned int n_points = g.points.size();
    const unsigned int n_dofs   = g.u.n_dofs();
    sorted_of.resize(n_points);
    for (unsigned int p = 0; p < n_points; ++p)
      sorted_of[g.order[p]] = p;
    const auto support = blocks_of_separated_functions(g);
    std::vector<std::vector<std::pair<unsigned int, unsigned int>>> copies(n_points);
    std::vector<WeakCopy>                                           weak;
    std::vector<unsigned int> local(n_points), stamp(n_points, 0);
    const auto                separated = [&](const unsigned int p) {
      return separates(g.points[p]);
    };
    for (unsigned int d = 0; d < n_dofs; ++d)
      {
        if (support[d].empty())
          continue;
        auto       parts = parts_of_support(g, d, support[d], local, stamp);
        const auto faces = faces_of_support(parts);
        if (faces.size() < 2)
          continue;
        // The part of most points keeps the function (the first of them in the points' order if
        // several); each other face takes a copy, but for the flanks next to a fold's tip, close
        // along the surface, where the self-contact finds no pairs ('Minimum arc length'): there
        // the grid keeps them together.
        const unsigned int keeper =
          *std::max_element(faces.begin(),
                            faces.end(),
                            [&parts](const unsigned int a, const unsigned int b) {
                              return parts.part[a].points < parts.part[b].points;
                            });
        const auto unsorted = [&g](std::vector<unsigned int> sorted) {
          for (auto &p : sorted)
            p = g.order[p];
          return sorted;
        };
        const auto keeper_surface = unsorted(parts.of_part(keeper, separated));
        for (const unsigned int face : faces)
          {
            if (face == keeper ||
                near_along_surface(g, unsorted(parts.of_part(face, separated)), keeper_surface))
              continue;
            const unsigned int copy = n_dofs + copy_of.size();
            copy_of.push_back(d);
            for (unsigned int m = 0; m < parts.members.size(); ++m)
              if (parts.parts.root(m) == face)
                copies[parts.members[m]].emplace_back(parts.position[m], copy);
            if (parts.part[face].weight < weak_share * parts.total && !g.u.refined())
              weak.push_back({copy,
                              d,
                              parts.of_part(face,
                                            [](unsigned int) {
                                              return true;
                                            }),
                              {},
                              parts.total});
            for (unsigned int m = 0; m < parts.members.size() && !weak.empty(); ++m)
              if (weak.back().copy == copy && parts.parts.root(m) != face)
                weak.back().others.push_back(parts.members[m]);
          }
      }
    tie_weak_copies(g, copies, copy_of, weak);
    return copies;
  }


  template <int dim>
  void
  FaceSeparation<dim>::tie_weak_copies(
    const Grouping                                                  &g,
    std::vector<std::vector<std::pair<unsigned int, unsigned int>>> &copies,
    std::vector<unsigned int>                                       &copy_of,
    const std::vector<WeakCopy>                                     &weak)
  {
    ties_.clear();
    const unsigned int n_dofs = g.u.n_dofs();
    control_point_of_dof.assign(n_dofs, dealii::numbers::invalid_unsigned_int);
    for (unsigned int i = 0; i < g.u.n_control_points(); ++i)
      if (const unsigned int dof = g.u.dof_of_control_point(i); dof < n_dofs)
        control_point_of_dof[dof] = i;
    std::vector<bool> weak_copies(copy_of.size(), false);
    for (const auto &w : weak)
      weak_copies[w.copy - n_dofs] = true;
    // A weak copy without a donor next to it (at a corner of the face, where only a diagonal
    // extrapolation reaches an interior cell) is no copy: its face keeps the function.
    std::vector<bool> removed(copy_of.size(), false);
    DonorSearch       search;
    search.state.assign(g.points.size(), 0);
    for (const auto &b : g.blocks)
      ++search.blocks_of_cell[b.u_cell];
    for (const auto &w : weak)
      {
        CopyTie tie;
        if (tie_weak_copy(g, copies, weak_copies, w, search, tie))
          ties_.push_back(std::move(tie));
        else
          removed[w.copy - n_dofs] = true;
      }
    if (std::find(removed.begin(), removed.end(), true) == removed.end())
      return;
    std::vector<unsigned int> renumbered(copy_of.size());
    std::vector<unsigned int> kept;
    for (unsigned int k = 0; k < copy_of.size(); ++k)
      if (!removed[k])
        {
          renumbered[k] = n_dofs + kept.size();
          kept.push_back(copy_of[k]);
        }
    copy_of            = std::move(kept);
    const auto new_dof = [&](const unsigned int dof) {
      return dof < n_dofs ? dof : renumbered[dof - n_dofs];
    };
    for (auto &list : copies)
      {
        list.erase(std::remove_if(list.begin(),
                                  list.end(),
                                  [&](const auto &entry) {
                                    return removed[entry.second - n_dofs];
                                  }),
                   list.end());
        for (auto &entry : list)
          entry.second = new_dof(entry.second);
      }
    for (auto &tie : ties_)
      {
        tie.copy = new_dof(tie.copy);
        for (auto &donor : tie.donors)
          donor.first = new_dof(donor.first);
      }
  }


  template <int dim>
  std::vector<unsigned int>
  FaceSeparation<dim>::reached_from_face(const Grouping             &g,
                                         const WeakCopy             &weak,
                                         std::vector<unsigned char> &state) const
  {
    // Breadth first over material neighbours from the face, never into the support's other
    // parts, no farther than 2(q+1) cells from the face's centre.
    const auto &space = g.u.space();
    double      h     = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      h = std::max(h, space.cell_size(d));
    const double       reach = 2. * (space.degree() + 1) * h;
    dealii::Point<dim> centre;
    for (const unsigned int m : weak.members)
      centre += g.points[m].x / static_cast<double>(weak.members.size());
    for (const unsigned int o : weak.others)
      state[o] = 2;
    std::vector<unsigned int> queue;
    for (const unsigned int m : weak.members)
      {
        state[m] = 1;
        queue.push_back(m);
      }
    for (unsigned int k = 0; k < queue.size(); ++k)
      {
        const auto [begin, end] = graph.neighbours(g.order[queue[k]]);
        for (auto j = begin; j != end; ++j)
          if (const unsigned int p = sorted_of[*j];
              state[p] == 0 && (g.points[p].x - centre).norm() <= reach)
            {
              state[p] = 1;
              queue.push_back(p);
            }
      }
    // The scratch back to unseen for the next copy.
    for (const unsigned int p : queue)
      state[p] = 0;
    for (const unsigned int o : weak.others)
      state[o] = 0;
    return queue;
  }


  template <int dim>
  int
  FaceSeparation<dim>::donor_block(
    const Grouping                                                        &g,
    const std::vector<std::vector<std::pair<unsigned int, unsigned int>>> &copies,
    const std::vector<bool>                                               &weak_copies,
    const WeakCopy                                                        &weak,
    DonorSearch                                                           &search,
    std::array<int, dim>                                                  &best_corner) const
  {
    const auto                          &space  = g.u.space();
    const int                            q      = space.degree();
    const unsigned int                   n_dofs = g.u.n_dofs();
    std::map<unsigned int, unsigned int> reached;
    for (const unsigned int p : reached_from_face(g, weak, search.state))
      ++reached[g.points[p].block];
    const auto kk = space.function_multi_index(control_point_of_dof[weak.function]);
    // A block wholly reached, alone in an interior cell, whose versions are no weak copies; the
    // nearest to the function as the extension picks its block (eq. (54)).
    double best_distance = std::numeric_limits<double>::max(), best_centre = best_distance;
    int    best = -1;
    for (const auto &[b, n] : reached)
      {
        const PointBlock &block = g.blocks[b];
        bool usable = n == block.end - block.first && search.blocks_of_cell[block.u_cell] == 1 &&
                      g.u.cell_kind(block.u_cell) == CellKind::interior;
        for (const auto &[position, copy] : copies[block.first])
          usable &= !weak_copies[copy - n_dofs];
        if (!usable)
          continue;
        std::array<int, dim> corner;
        corner.fill(std::numeric_limits<int>::max());
        for (const unsigned int dof : g.u.cell_dofs(block.u_cell))
          {
            const auto m = space.function_multi_index(control_point_of_dof[dof]);
            for (unsigned int d = 0; d < dim; ++d)
              corner[d] = std::min(corner[d], static_cast<int>(m[d]));
          }
        double distance = 0., centre = 0.;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const int k   = kk[d];
            const int gap = std::max({0, corner[d] - k, k - (corner[d] + q)});
            distance += gap * gap;
            centre += (k - corner[d] - 0.5 * q) * (k - corner[d] - 0.5 * q);
          }
        if (distance < best_distance - 1e-12 ||
            (distance < best_distance + 1e-12 && centre < best_centre - 1e-12))
          {
            best          = b;
            best_corner   = corner;
            best_distance = distance;
            best_centre   = centre;
          }
      }
    // Only a donor next to the function along one direction (weights up to 3 for q = 2): the
    // diagonal extrapolation to a face's corner amplifies its donors' motion (weights up to 9)
    // and Newton did not converge with it.
    return best_distance > 1. + 1e-12 ? -1 : best;
  }


  template <int dim>
  bool
  FaceSeparation<dim>::tie_weak_copy(
    const Grouping                                                        &g,
    const std::vector<std::vector<std::pair<unsigned int, unsigned int>>> &copies,
    const std::vector<bool>                                               &weak_copies,
    const WeakCopy                                                        &weak,
    DonorSearch                                                           &search,
    CopyTie                                                               &tie) const
  {
    std::array<int, dim> corner;
    const int            best = donor_block(g, copies, weak_copies, weak, search, corner);
    if (best < 0)
      return false;
    const auto       &space = g.u.space();
    const int         q     = space.degree();
    const auto        kk    = space.function_multi_index(control_point_of_dof[weak.function]);
    const PointBlock &donor = g.blocks[best];
    const auto       &dofs  = g.u.cell_dofs(donor.u_cell);
    tie.copy                = weak.copy;
    tie.cell                = g.blocks[g.points[weak.members.front()].block].u_cell;
    tie.donor_cell          = donor.u_cell;
    tie.donors.clear();
    for (unsigned int a = 0; a < dofs.size(); ++a)
      {
        // Tensor-product Lagrange extrapolation in the index, eq. (54).
        const auto m = space.function_multi_index(control_point_of_dof[dofs[a]]);
        double     E = 1.;
        for (unsigned int d = 0; d < dim; ++d)
          for (int s = corner[d]; s <= corner[d] + q; ++s)
            if (s != static_cast<int>(m[d]))
              E *= static_cast<double>(static_cast<int>(kk[d]) - s) / (static_cast<int>(m[d]) - s);
        unsigned int version = dofs[a];
        for (const auto &[position, copy] : copies[donor.first])
          if (position == a)
            version = copy;
        if (version == weak.copy)
          return false;
        tie.donors.emplace_back(version, E);
      }
    double h = 0.;
    for (unsigned int d = 0; d < dim; ++d)
      h = std::max(h, space.cell_size(d));
    tie.stiffness = g.points[weak.members.front()].gel->shear_modulus() * weak.total / (h * h);
    return true;
  }


  template <int dim>
  Separation::SupportParts
  FaceSeparation<dim>::parts_of_support(const Grouping                  &g,
                                        const unsigned int               d,
                                        const std::vector<unsigned int> &blocks,
                                        std::vector<unsigned int>       &local,
                                        std::vector<unsigned int>       &stamp) const
  {
    Separation::SupportParts support;
    auto &[members, position, parts, part, total] = support;
    for (const unsigned int b : blocks)
      {
        const auto        &dofs = g.u.cell_dofs(g.blocks[b].u_cell, g.blocks[b].u_piece);
        const unsigned int a    = std::find(dofs.begin(), dofs.end(), d) - dofs.begin();
        for (unsigned int p = g.blocks[b].first; p < g.blocks[b].end; ++p)
          {
            local[p] = members.size();
            stamp[p] = d + 1;
            members.push_back(p);
            position.push_back(a);
          }
      }
    // Joined by neighbours that are in the support too (stamped with this function).
    parts = Separation::Parts(members.size());
    for (unsigned int m = 0; m < members.size(); ++m)
      {
        const auto [begin, end] = graph.neighbours(g.order[members[m]]);
        for (auto j = begin; j != end; ++j)
          if (const unsigned int q = sorted_of[*j]; stamp[q] == d + 1)
            parts.join(m, local[q]);
      }
    part.assign(members.size(), Separation::Part());
    for (unsigned int m = 0; m < members.size(); ++m)
      {
        const auto &r    = g.points[members[m]];
        auto       &into = part[parts.root(m)];
        ++into.points;
        into.separated_surface |= separates(r);
        if (r.kind == PointKind::volume)
          {
            const double w = r.measure * std::abs(g.u_values[r.u_offset + position[m]]);
            into.weight += w;
            total += w;
          }
      }
    return support;
  }


  template <int dim>
  std::vector<unsigned int>
  FaceSeparation<dim>::faces_of_support(Separation::SupportParts &support) const
  {
    // A face of its own: a part with a separated surface point and more than 1 % of the weight
    // (slivers cut off by the edge of the support have none of the first or little of the second).
    std::vector<unsigned int> faces;
    for (unsigned int m = 0; m < support.members.size(); ++m)
      if (support.parts.root(m) == m && support.part[m].separated_surface &&
          support.part[m].weight > 0.01 * support.total)
        faces.push_back(m);
    return faces;
  }


  template <int dim>
  bool
  FaceSeparation<dim>::near_along_surface(const Grouping                  &g,
                                          const std::vector<unsigned int> &from,
                                          const std::vector<unsigned int> &to) const
  {
    // Shortest paths from the points of @p from over neighbouring surface points, their lengths
    // in the initial configuration, no farther than along_surface. (Points are unsorted indices.)
    std::unordered_map<unsigned int, double> distance;
    using Entry = std::pair<double, unsigned int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    for (const unsigned int i : from)
      {
        distance[i] = 0.;
        queue.emplace(0., i);
      }
    const std::unordered_set<unsigned int> targets(to.begin(), to.end());
    const auto &record = [&](const unsigned int i) -> const PointRecord<dim> & {
      return g.points[sorted_of[i]];
    };
    while (!queue.empty())
      {
        const auto [d, i] = queue.top();
        queue.pop();
        if (d > distance[i])
          continue;
        if (targets.count(i) > 0)
          return true;
        const auto [begin, end] = graph.neighbours(i);
        for (auto j = begin; j != end; ++j)
          {
            if (record(*j).kind == PointKind::volume)
              continue;
            const double next = d + (record(*j).X0 - record(i).X0).norm();
            if (next > along_surface)
              continue;
            const auto known = distance.find(*j);
            if (known == distance.end() || next < known->second)
              {
                distance[*j] = next;
                queue.emplace(next, *j);
              }
          }
      }
    return false;
  }


  template class FaceSeparation<2>;
  template class FaceSeparation<3>;
} // namespace GelMPM
