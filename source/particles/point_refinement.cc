#include <gelmpm/particles/material_state.h>
#include <gelmpm/particles/point_location.h>
#include <gelmpm/particles/point_refinement.h>
#include <gelmpm/particles/property_layout.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <boost/serialization/utility.hpp>
#include <boost/serialization/vector.hpp>
#include <cmath>
#include <map>

namespace GelMPM
{
  template <int dim>
  std::vector<dealii::Tensor<1, dim>>
  volume_point_offsets(const std::array<double, dim> &sides, const unsigned int parts)
  {
    unsigned int n_children = 1;
    for (unsigned int d = 0; d < dim; ++d)
      n_children *= parts;
    std::vector<dealii::Tensor<1, dim>> offsets(n_children);
    for (unsigned int k = 0; k < n_children; ++k)
      {
        unsigned int rest = k;
        for (unsigned int d = 0; d < dim; ++d)
          {
            offsets[k][d] = ((rest % parts + 0.5) / parts - 0.5) * sides[d];
            rest /= parts;
          }
      }
    return offsets;
  }


  namespace
  {
    /**
     * What a family's merge needs of one member @p point: its id, its position and its
     * properties, in this order.
     */
    template <int dim, typename Iterator>
    std::vector<double>
    family_member(const Iterator &point)
    {
      const auto          properties = point->get_properties();
      std::vector<double> member{static_cast<double>(point->get_id())};
      const auto          position = position_of(point->get_location(), properties);
      for (unsigned int d = 0; d < dim; ++d)
        member.push_back(position[d]);
      member.insert(member.end(), properties.begin(), properties.end());
      return member;
    }


    /**
     * Per family of @p families (keyed by parent) that this rank holds only part of, the
     * members (family_member()) that every rank holds of it: a family whose points lie on
     * either side of the partition is merged from these, the same merged point as on one rank,
     * instead of siblings that wait until they share a rank. Empty on one rank.
     */
    template <int dim, typename Iterator>
    std::map<std::vector<long>, std::vector<std::vector<double>>>
    members_of_partial_families(const std::map<std::vector<long>, std::vector<Iterator>> &families,
                                const MPI_Comm communicator)
    {
      std::map<std::vector<long>, std::vector<std::vector<double>>> spread;
      if (dealii::Utilities::MPI::n_mpi_processes(communicator) == 1)
        return spread;
      std::vector<std::pair<std::vector<long>, std::vector<double>>> partial;
      for (const auto &[key, members] : families)
        if (members.size() < (1u << dim))
          for (const auto &member : members)
            partial.emplace_back(key, family_member<dim>(member));
      for (auto &rank : dealii::Utilities::MPI::all_gather(communicator, partial))
        for (auto &[key, member] : rank)
          spread[key].push_back(std::move(member));
      return spread;
    }


    /**
     * A unit tangent of the facet with unit normal @p n in 3D: the coordinate axis most nearly
     * in the facet, projected onto it (the first such axis on a tie).
     */
    dealii::Tensor<1, 3>
    facet_tangent(const dealii::Tensor<1, 3> &n)
    {
      unsigned int axis = 0;
      for (unsigned int d = 1; d < 3; ++d)
        if (std::abs(n[d]) < std::abs(n[axis]))
          axis = d;
      dealii::Tensor<1, 3> t;
      t[axis] = 1.;
      t -= (t * n) * n;
      return t / t.norm();
    }
  } // namespace


  template <int dim>
  std::vector<dealii::Tensor<1, dim>>
  surface_element_offsets(const dealii::Tensor<1, dim> &normal_area, const unsigned int parts)
  {
    const double                                area = normal_area.norm();
    std::array<dealii::Tensor<1, dim>, dim - 1> tangents;
    double                                      side = area;
    if constexpr (dim == 2)
      {
        tangents[0][0] = -normal_area[1] / area;
        tangents[0][1] = normal_area[0] / area;
      }
    else
      {
        const dealii::Tensor<1, 3> n = normal_area / area;
        tangents[0]                  = facet_tangent(n);
        tangents[1]                  = dealii::cross_product_3d(n, tangents[0]);
        side                         = std::sqrt(area);
      }
    unsigned int n_children = 1;
    for (unsigned int d = 0; d + 1 < dim; ++d)
      n_children *= parts;
    std::vector<dealii::Tensor<1, dim>> offsets(n_children);
    for (unsigned int k = 0; k < n_children; ++k)
      {
        unsigned int rest = k;
        for (unsigned int d = 0; d + 1 < dim; ++d)
          {
            offsets[k] += ((rest % parts + 0.5) / parts - 0.5) * side * tangents[d];
            rest /= parts;
          }
      }
    return offsets;
  }


  namespace
  {
    template <int dim>
    using Layout = PropertyLayout<dim>;

    /** A point to be inserted: its location, properties and the cell its parent lies in. */
    template <int dim>
    struct Child
    {
      dealii::Point<dim>                                        location;
      std::vector<double>                                       properties;
      typename dealii::Triangulation<dim>::active_cell_iterator cell;
    };


    /** The offsets in the initial configuration of the children of the point @p properties. */
    template <int dim, typename Properties>
    std::vector<dealii::Tensor<1, dim>>
    child_offsets(const Properties          &properties,
                  const unsigned int         parts,
                  const BackgroundGrid<dim> &grid,
                  const unsigned int         points_per_cell)
    {
      const unsigned int spacing = std::lround(properties[Layout<dim>::spacing_level]);
      if (kind_of(properties) == PointKind::volume)
        {
          std::array<double, dim> sides;
          for (unsigned int d = 0; d < dim; ++d)
            sides[d] = grid.cell_size(d) / (points_per_cell * double(1u << spacing));
          return volume_point_offsets<dim>(sides, parts);
        }
      dealii::Tensor<1, dim> normal_area;
      for (unsigned int d = 0; d < dim; ++d)
        normal_area[d] = properties[Layout<dim>::normal_area_0 + d];
      // An axisymmetric scene's N_0 A_0 is revolved: the element's own is 1 / (2 pi R_0) of it.
      if (grid.axisymmetric)
        normal_area /= 2. * dealii::numbers::PI * properties[Layout<dim>::position_0];
      return surface_element_offsets<dim>(normal_area, parts);
    }


    /**
     * The properties of the child at @p offset (initial configuration) of the point with
     * properties @p parent at @p x, one of @p n_children; its current position in @p x_child.
     */
    template <int dim, typename Properties>
    std::vector<double>
    child_properties(const Properties             &parent,
                     const dealii::Point<dim>     &x,
                     const dealii::Tensor<1, dim> &offset,
                     const unsigned int            n_children,
                     const unsigned int            level,
                     const BackgroundGrid<dim>    &grid,
                     const MaterialRegions<dim>   &regions,
                     dealii::Point<dim>           &x_child)
    {
      std::vector<double> child(parent.begin(), parent.end());
      const double        lambda_0 = material_state_of(regions, parent).gel->lambda_0();
      const auto          F_n      = deformation_gradient_of<dim>(parent) / lambda_0;
      x_child                      = x + F_n * offset;
      for (unsigned int d = 0; d < dim; ++d)
        child[Layout<dim>::position_0 + d] += offset[d];
      // Every measure of an axisymmetric scene is revolved: 2 pi R_0 in the initial
      // configuration, 2 pi r_n in the current one.
      double initial = 1. / n_children, current = 1. / n_children;
      if (grid.axisymmetric)
        {
          const double R_0 = parent[Layout<dim>::position_0];
          initial *= child[Layout<dim>::position_0] / R_0;
          current *= x_child[0] / x[0];
          if constexpr (dim == 2)
            child[Layout<dim>::out_of_plane] =
              lambda_0 * x_child[0] / child[Layout<dim>::position_0];
        }
      child[Layout<dim>::measure_0] *= initial;
      child[Layout<dim>::measure_n] *= current;
      for (unsigned int d = 0; d < dim; ++d)
        {
          child[Layout<dim>::normal_area_0 + d] *= initial;
          child[Layout<dim>::normal_area_n + d] *= current;
        }
      child[Layout<dim>::spacing_level] = level;
      return child;
    }


    /** The reference coordinates of @p x in the box cell @p cell (outside [0, 1] if outside). */
    template <int dim>
    dealii::Point<dim>
    reference_in(const typename dealii::Triangulation<dim>::active_cell_iterator &cell,
                 const dealii::Point<dim>                                        &x)
    {
      const auto        &lo = cell->vertex(0);
      const auto        &hi = cell->vertex(dealii::GeometryInfo<dim>::vertices_per_cell - 1);
      dealii::Point<dim> reference;
      for (unsigned int d = 0; d < dim; ++d)
        reference[d] = (x[d] - lo[d]) / (hi[d] - lo[d]);
      return reference;
    }
  } // namespace


  template <int dim>
  unsigned long
  split_points_to_leaves(dealii::Particles::ParticleHandler<dim> &particles,
                         const BackgroundGrid<dim>               &grid,
                         const MaterialRegions<dim>              &regions,
                         const unsigned int                       points_per_cell,
                         const dealii::Triangulation<dim>        &triangulation)
  {
    std::vector<Child<dim>> children;
    for (auto particle = particles.begin(); particle != particles.end(); ++particle)
      {
        auto               properties = particle->get_properties();
        const long         spacing    = std::lround(properties[Layout<dim>::spacing_level]);
        const auto         x          = position_of(particle->get_location(), properties);
        const unsigned int level      = grid.refinement_level(particle->get_location());
        if (spacing < 0 || level <= static_cast<unsigned long>(spacing))
          continue;
        const auto offsets =
          child_offsets<dim>(properties, 1u << (level - spacing), grid, points_per_cell);
        const std::vector<double> parent(properties.begin(), properties.end());
        for (unsigned int k = 0; k < offsets.size(); ++k)
          {
            dealii::Point<dim> x_child;
            auto               child = child_properties<dim>(parent,
                                               x,
                                               offsets[k],
                                               offsets.size(),
                                               level,
                                               grid,
                                               regions,
                                               x_child);
            // The edge offset stays: the child's location is its position less it, as the
            // parent's.
            dealii::Point<dim> location = x_child;
            for (unsigned int d = 0; d < dim; ++d)
              location[d] -= child[Layout<dim>::edge_offset + d];
            if (k == 0)
              {
                std::copy(child.begin(), child.end(), properties.begin());
                particle->set_location(location);
                particle->set_reference_location(
                  reference_in<dim>(particle->get_surrounding_cell(), location));
              }
            else
              children.push_back({location, std::move(child), particle->get_surrounding_cell()});
          }
      }
    const MPI_Comm communicator = triangulation.get_communicator();
    const auto     counts =
      dealii::Utilities::MPI::all_gather(communicator, static_cast<unsigned long>(children.size()));
    dealii::types::particle_index next  = particles.get_next_free_particle_index();
    unsigned long                 added = 0;
    for (unsigned int rank = 0; rank < counts.size(); ++rank)
      {
        if (rank < dealii::Utilities::MPI::this_mpi_process(communicator))
          next += counts[rank];
        added += counts[rank];
      }
    for (auto &child : children)
      particles.insert_particle(child.location,
                                reference_in<dim>(child.cell, child.location),
                                next++,
                                child.cell,
                                dealii::make_array_view(child.properties));
    if (added > 0)
      sort_into_cells(particles, grid, triangulation);
    particles.update_cached_numbers();
    return added;
  }


  namespace
  {
    /**
     * The key of the parent of the volume point with @p properties on the generator's lattice of
     * sub-cells: its spacing level s, its region and the multi-index of the sub-cell of spacing
     * s - 1 that holds its X_0. A point of spacing s stands for the sub-cell of side
     * h / (points per cell 2^s) centred on X_0; its parent's sub-cell holds it.
     */
    template <int dim, typename Properties>
    std::vector<long>
    parent_key(const Properties          &properties,
               const BackgroundGrid<dim> &grid,
               const unsigned int         points_per_cell)
    {
      const long        spacing = std::lround(properties[Layout<dim>::spacing_level]);
      std::vector<long> key     = {spacing, std::lround(properties[Layout<dim>::region])};
      for (unsigned int d = 0; d < dim; ++d)
        {
          const double side  = grid.cell_size(d) / (points_per_cell * double(1u << spacing));
          const long   index = std::lround(
            std::floor((properties[Layout<dim>::position_0 + d] - grid.lower[d]) / side));
          key.push_back(index >> 1);
        }
      return key;
    }


    /**
     * The properties of the point that the volume points @p children (the 2^dim children of one
     * parent) merge into, and its current position in @p x: V_0 and V_n summed, X_0, x, mu, the
     * increments and the edge offset their means weighted by their shares of the parent's
     * sub-cell (V_0; V_0 / R_0 in an axisymmetric scene), F its weighted mean scaled
     * so that the point's J is the children's V_n / V_0 (the volume, hence the solvent, is
     * kept), the hoop stretch of an axisymmetric scene lambda_0 r / R of the merged point.
     */
    template <int dim>
    std::vector<double>
    merged_properties(const std::vector<std::vector<double>> &children,
                      const std::vector<dealii::Point<dim>>  &positions,
                      const BackgroundGrid<dim>              &grid,
                      const MaterialRegions<dim>             &regions,
                      dealii::Point<dim>                     &x)
    {
      std::vector<double> merged(children[0].size(), 0.);
      double              V_0 = 0., V_n = 0.;
      for (const auto &child : children)
        {
          V_0 += child[Layout<dim>::measure_0];
          V_n += child[Layout<dim>::measure_n];
        }
      // The weights of the children's shares of the parent's sub-cell in the plane (meridian
      // plane): V_0, divided by 2 pi R_0 in an axisymmetric scene, where V_0-weighted means would
      // move the point outwards.
      std::vector<double> weights(children.size());
      double              total = 0.;
      for (unsigned int k = 0; k < children.size(); ++k)
        {
          weights[k] = children[k][Layout<dim>::measure_0] /
                       (grid.axisymmetric ? children[k][Layout<dim>::position_0] : 1.);
          total += weights[k];
        }
      x = dealii::Point<dim>();
      for (unsigned int k = 0; k < children.size(); ++k)
        {
          const double weight = weights[k] / total;
          for (unsigned int i = 0; i < merged.size(); ++i)
            merged[i] += weight * children[k][i];
          x += weight * positions[k];
        }
      for (const unsigned int i : {Layout<dim>::kind, Layout<dim>::piece, Layout<dim>::region})
        merged[i] = children[0][i];
      merged[Layout<dim>::spacing_level] = children[0][Layout<dim>::spacing_level] - 1;
      merged[Layout<dim>::measure_0]     = V_0;
      merged[Layout<dim>::measure_n]     = V_n;
      const double lambda_0              = material_state_of(regions, merged).gel->lambda_0();
      double       hoop                  = 1.;
      if constexpr (dim == 2)
        if (grid.axisymmetric)
          {
            hoop                              = x[0] / merged[Layout<dim>::position_0];
            merged[Layout<dim>::out_of_plane] = lambda_0 * hoop;
          }
      const auto   F = deformation_gradient_of<dim>(merged);
      const double scale =
        std::pow(V_n / V_0 * std::pow(lambda_0, dim) / (hoop * dealii::determinant(F)), 1. / dim);
      for (unsigned int i = 0; i < dim * dim; ++i)
        merged[Layout<dim>::F + i] *= scale;
      return merged;
    }
  } // namespace


  template <int dim>
  unsigned long
  merge_points_to_leaves(dealii::Particles::ParticleHandler<dim> &particles,
                         const BackgroundGrid<dim>               &grid,
                         const MaterialRegions<dim>              &regions,
                         const unsigned int                       points_per_cell,
                         const dealii::Triangulation<dim>        &triangulation)
  {
    using Iterator = typename dealii::Particles::ParticleHandler<dim>::particle_iterator;
    std::map<std::vector<long>, std::vector<Iterator>> families;
    for (auto particle = particles.begin(); particle != particles.end(); ++particle)
      {
        const auto properties = particle->get_properties();
        const long spacing    = std::lround(properties[Layout<dim>::spacing_level]);
        if (kind_of(properties) != PointKind::volume || spacing <= 0 ||
            grid.refinement_level(particle->get_location()) >= static_cast<unsigned long>(spacing))
          continue;
        families[parent_key<dim>(properties, grid, points_per_cell)].push_back(particle);
      }
    const MPI_Comm        communicator = triangulation.get_communicator();
    auto                  spread       = members_of_partial_families<dim>(families, communicator);
    std::vector<Iterator> removed;
    for (auto &[key, members] : families)
      {
        std::vector<std::vector<double>> gathered;
        if (members.size() == (1u << dim))
          for (const auto &member : members)
            gathered.push_back(family_member<dim>(member));
        else if (const auto found = spread.find(key);
                 found != spread.end() && found->second.size() == (1u << dim))
          gathered = found->second;
        // Only a whole family, all of whose points lie in leaves coarser than their spacing.
        if (gathered.empty())
          continue;
        // In the order of their ids on every partition: the sums are added alike, and the
        // member of the smallest id keeps the merged point.
        std::sort(gathered.begin(), gathered.end());
        std::sort(members.begin(), members.end(), [](const Iterator &a, const Iterator &b) {
          return a->get_id() < b->get_id();
        });
        std::vector<std::vector<double>> children;
        std::vector<dealii::Point<dim>>  positions;
        for (const auto &member : gathered)
          {
            dealii::Point<dim> position;
            for (unsigned int d = 0; d < dim; ++d)
              position[d] = member[1 + d];
            positions.push_back(position);
            children.emplace_back(member.begin() + 1 + dim, member.end());
          }
        const bool keeper_here = static_cast<double>(members[0]->get_id()) == gathered[0][0];
        if (keeper_here)
          {
            dealii::Point<dim> x;
            const auto merged = merged_properties<dim>(children, positions, grid, regions, x);
            auto       first  = members[0];
            std::copy(merged.begin(), merged.end(), first->get_properties().begin());
            dealii::Point<dim> location = x;
            for (unsigned int d = 0; d < dim; ++d)
              location[d] -= merged[Layout<dim>::edge_offset + d];
            // The merged point may lie in a cell of another rank: sort_into_cells() hands it on.
            first->set_location(location);
            first->set_reference_location(
              reference_in<dim>(first->get_surrounding_cell(), location));
          }
        removed.insert(removed.end(), members.begin() + (keeper_here ? 1 : 0), members.end());
      }
    particles.remove_particles(removed);
    const auto total = dealii::Utilities::MPI::sum(static_cast<unsigned long>(removed.size()),
                                                   triangulation.get_communicator());
    if (total > 0)
      sort_into_cells(particles, grid, triangulation);
    particles.update_cached_numbers();
    return total;
  }


  template std::vector<dealii::Tensor<1, 2>>
  volume_point_offsets<2>(const std::array<double, 2> &, const unsigned int);
  template std::vector<dealii::Tensor<1, 3>>
  volume_point_offsets<3>(const std::array<double, 3> &, const unsigned int);
  template std::vector<dealii::Tensor<1, 2>>
  surface_element_offsets<2>(const dealii::Tensor<1, 2> &, const unsigned int);
  template std::vector<dealii::Tensor<1, 3>>
  surface_element_offsets<3>(const dealii::Tensor<1, 3> &, const unsigned int);
  template unsigned long
  split_points_to_leaves<2>(dealii::Particles::ParticleHandler<2> &,
                            const BackgroundGrid<2> &,
                            const MaterialRegions<2> &,
                            const unsigned int,
                            const dealii::Triangulation<2> &);
  template unsigned long
  merge_points_to_leaves<2>(dealii::Particles::ParticleHandler<2> &,
                            const BackgroundGrid<2> &,
                            const MaterialRegions<2> &,
                            const unsigned int,
                            const dealii::Triangulation<2> &);
  template unsigned long
  merge_points_to_leaves<3>(dealii::Particles::ParticleHandler<3> &,
                            const BackgroundGrid<3> &,
                            const MaterialRegions<3> &,
                            const unsigned int,
                            const dealii::Triangulation<3> &);
  template unsigned long
  split_points_to_leaves<3>(dealii::Particles::ParticleHandler<3> &,
                            const BackgroundGrid<3> &,
                            const MaterialRegions<3> &,
                            const unsigned int,
                            const dealii::Triangulation<3> &);
} // namespace GelMPM
