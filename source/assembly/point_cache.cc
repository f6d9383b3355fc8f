#include <gelmpm/assembly/face_separation.h>
#include <gelmpm/assembly/point_cache.h>
#include <gelmpm/core/collective.h>
#include <gelmpm/core/format_point.h>
#include <gelmpm/core/non_physical_state.h>

#include <deal.II/base/parallel.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <stdexcept>

namespace GelMPM
{
  using dealii::Point;
  using dealii::Tensor;

  namespace
  {
    /** The projector onto the displacement components a piece constrains. */
    template <int dim>
    Tensor<2, dim>
    constraint_projector(const typename BoundaryPiece<dim>::DisplacementCondition condition,
                         const Tensor<1, dim>                                    &normal)
    {
      using Condition = typename BoundaryPiece<dim>::DisplacementCondition;
      Tensor<2, dim> projector;
      switch (condition)
        {
          case Condition::free:
            break;
          case Condition::fixed:
            projector = dealii::unit_symmetric_tensor<dim>();
            break;
          case Condition::normal:
            projector = outer(normal, normal);
            break;
          case Condition::tangential:
            projector =
              dealii::Tensor<2, dim>(dealii::unit_symmetric_tensor<dim>()) - outer(normal, normal);
            break;
        }
      return projector;
    }
  } // namespace


  template <int dim>
  PointCache<dim>::PointCache(const MaterialRegions<dim>    &materials,
                              const BoundaryConditions<dim> &boundary_conditions,
                              DiscreteSpaces<dim>           &spaces,
                              const MPI_Comm                 communicator)
    : materials(materials)
    , boundary_conditions(boundary_conditions)
    , spaces(spaces)
    , communicator(communicator)
  {}


  template <int dim>
  PointCache<dim>::~PointCache() = default;


  template <int dim>
  void
  PointCache<dim>::separate_faces(std::vector<bool> pieces, const double along_surface)
  {
    const bool any = std::find(pieces.begin(), pieces.end(), true) != pieces.end();
    if (any && Collective::is_parallel(communicator))
      throw std::logic_error("PointCache::separate_faces: one MPI rank only");
    separation = any ? std::make_unique<FaceSeparation<dim>>(std::move(pieces),
                                                             along_surface,
                                                             spaces.axisymmetric())
                     : nullptr;
  }


  template <int dim>
  const std::vector<CopyTie> &
  PointCache<dim>::copy_ties() const
  {
    static const std::vector<CopyTie> none;
    return separation && !spaces.u_copies().empty() ? separation->ties() : none;
  }


  template <int dim>
  std::vector<unsigned int>
  PointCache<dim>::separate_supports()
  {
    std::vector<unsigned int> copy_of;
    const auto                copies =
      separation->copies_of_points({points_, blocks_, order_, u_values, spaces.u()}, copy_of);
    spaces.set_u_copies(copy_of);
    // The sides of a block: its points with one list of copies each.
    std::vector<unsigned int> sides(points_.size(), 0);
    for (const PointBlock &b : blocks_)
      {
        std::vector<const std::vector<std::pair<unsigned int, unsigned int>> *> lists;
        for (unsigned int p = b.first; p < b.end; ++p)
          {
            if (copies[p].empty())
              continue;
            const auto known = std::find_if(lists.begin(), lists.end(), [&](const auto *list) {
              return *list == copies[p];
            });
            sides[order_[p]] = (known - lists.begin()) + 1;
            if (known != lists.end())
              continue;
            lists.push_back(&copies[p]);
            std::vector<unsigned int> dofs = u_dofs(b);
            for (const auto &[a, copy] : copies[p])
              dofs[a] = copy;
            side_lists_[{b.u_cell, b.u_piece, static_cast<unsigned int>(lists.size())}] =
              own_u_dofs_.size();
            // The step's separation, flattened: the pattern follows it.
            separation_.insert(separation_.end(), {b.u_cell, b.u_piece});
            separation_.insert(separation_.end(), dofs.begin(), dofs.end());
            own_u_dofs_.push_back(std::move(dofs));
          }
      }
    separation_.insert(separation_.end(), copy_of.begin(), copy_of.end());
    return sides;
  }


  template <int dim>
  void
  PointCache<dim>::gather(dealii::Particles::ParticleHandler<dim> &particle_handler)
  {
    classify_cells(particle_handler);

    std::vector<PointRecord<dim>>  unsorted;
    std::vector<particle_iterator> its;
    std::vector<unsigned int>      cells, pieces;
    unsorted.reserve(particle_handler.n_locally_owned_particles());
    std::string failure;
    try
      {
        for (auto particle = particle_handler.begin(); particle != particle_handler.end();
             ++particle)
          {
            unsorted.push_back(unpack_point(*particle));
            its.push_back(particle);
            const auto [cell, piece] = cell_and_piece_of_point(unsorted.back());
            cells.push_back(cell);
            pieces.push_back(piece);
          }
      }
    catch (const std::runtime_error &e)
      {
        failure = e.what();
      }
    Collective::agree_on_failure<std::runtime_error>(communicator, failure);
    own_u_dofs_.clear();
    side_lists_.clear();
    separation_.clear();
    if (!separation)
      {
        group_points(unsorted, its, cells, pieces);
        evaluate_shape_functions();
        return;
      }
    // Separated faces: the parts of each support are judged on the cells' own functions, then
    // the points are grouped again with the copies they use.
    spaces.set_u_copies({});
    separation->find_neighbours(unsorted, its);
    separation->anchor_surface_points(unsorted, cells, pieces);
    group_points(unsorted, its, cells, pieces);
    evaluate_shape_functions();
    const auto sides = separate_supports();
    if (spaces.u_copies().empty())
      return;
    group_points(unsorted, its, cells, pieces, sides);
    evaluate_shape_functions();
  }


  template <int dim>
  void
  PointCache<dim>::classify_cells(const dealii::Particles::ParticleHandler<dim> &particle_handler)
  {
    // The cells that hold volume points decide the classification (§3.5).
    const auto         &u_space = spaces.u_space();
    std::vector<double> holder(u_space.n_cells(), 0.);
    const double        this_rank = dealii::Utilities::MPI::this_mpi_process(communicator);
    std::string         failure;
    // Refined grids: the leaf cells with volume points decide the unknowns too.
    std::vector<bool> leaf_has_material;
    if (spaces.refined())
      leaf_has_material.assign(spaces.u_hierarchy().n_leaf_cells(), false);
    for (const auto &particle : particle_handler)
      {
        const Point<dim> x = particle.get_location();
        unsigned int     cell;
        try
          {
            cell = u_space.cell_containing(x);
          }
        catch (const std::out_of_range &)
          {
            failure = "a material point at " + format_point(x) +
                      " has left the background grid; enlarge 'Background grid/Lower corner' "
                      "and 'Upper corner'";
            break;
          }
        if (kind_of(particle.get_properties()) == PointKind::volume)
          {
            holder[cell] = this_rank + 1.;
            if (!leaf_has_material.empty())
              leaf_has_material[spaces.u_hierarchy().leaf_cell_containing(x)] = true;
          }
      }
    Collective::agree_on_failure<std::runtime_error>(communicator, failure);
    // The volume points of a cell are all on the rank that owns the cell: the sum over the ranks
    // is that rank + 1, and tells every rank the classification and who holds each active cell.
    Collective::sum_in_place(communicator, holder);
    if (!leaf_has_material.empty() && Collective::is_parallel(communicator))
      {
        // A leaf's points lie on the rank that owns its cell: every rank needs all leaves.
        std::vector<double> leaf_count(leaf_has_material.begin(), leaf_has_material.end());
        Collective::sum_in_place(communicator, leaf_count);
        for (unsigned int l = 0; l < leaf_count.size(); ++l)
          leaf_has_material[l] = leaf_count[l] > 0.;
      }
    std::vector<bool> has_material(u_space.n_cells(), false);
    cell_holder_.assign(u_space.n_cells(), dealii::numbers::invalid_unsigned_int);
    for (unsigned int c = 0; c < holder.size(); ++c)
      if (holder[c] > 0.)
        {
          has_material[c] = true;
          cell_holder_[c] = static_cast<unsigned int>(holder[c]) - 1;
        }
    spaces.reinit(has_material, leaf_has_material);
    n_active_cells_      = std::count(has_material.begin(), has_material.end(), true);
    classification_      = std::move(has_material);
    leaf_classification_ = std::move(leaf_has_material);
  }


  template <int dim>
  PointRecord<dim>
  PointCache<dim>::unpack_point(const dealii::Particles::ParticleAccessor<dim> &particle) const
  {
    using Layout           = PropertyLayout<dim>;
    const auto       props = particle.get_properties();
    PointRecord<dim> r;
    r.kind    = kind_of(props);
    r.piece   = piece_of(props);
    r.measure = props[Layout::measure_n];
    r.x       = particle.get_location();
    for (unsigned int d = 0; d < dim; ++d)
      {
        r.edge_offset[d] = props[Layout::edge_offset + d];
        r.X0[d]          = props[Layout::position_0 + d];
        r.u_n[d]         = r.x[d] + r.edge_offset[d] - r.X0[d];
        r.du_last[d]     = props[Layout::increment + d];
      }
    r.F_p      = deformation_gradient_of<dim>(props);
    r.mu_n     = props[Layout::mu];
    r.dmu_last = props[Layout::mu_increment];
    // The point's material state, from the one place that maps a point to its constants.
    const auto material = material_state_of(materials, props);
    r.region            = material.region;
    r.gel               = material.gel;
    if (spaces.axisymmetric() && r.X0[0] > 0.)
      {
        r.radius = r.x[0] + r.edge_offset[0];
        r.hoop   = out_of_plane_stretch_of<dim>(props);
      }
    try
      {
        r.mobility = r.axisymmetric() ? r.gel->mobility(r.F_p, r.hoop) : r.gel->mobility(r.F_p);
      }
    catch (const NonPhysicalState &e)
      {
        // A converged step passed every point that assembles its state; a surface point
        // carries F only for its normal and its mobility, and where the surface folds (a
        // crease closing) its F alone can leave the physical range.
        throw NonPhysicalState(
          std::string(e.what()) + " at the " +
          (r.kind == PointKind::volume
             ? std::string("volume point")
             : "surface point" + (r.piece >= 0
                                    ? " of '" + boundary_conditions.piece(r.piece).name + "'"
                                    : std::string())) +
          " at x = " + format_point(r.x) + " (X_0 = " + format_point(r.X0) + ")" +
          (r.kind == PointKind::volume
             ? std::string()
             : ": a surface point's own state (used for its normal and mobility only) leaves the "
               "range where the surface folds, its points pressed together along it as where a "
               "crease closes, and on a refined grid where the surface crosses cut leaf cells "
               "(doc/own_scenes.md, section 7)"));
      }
    // Surface points on the axis of an axisymmetric scene have no area (2 pi R = 0).
    r.assembled = ((r.kind == PointKind::volume) || (r.piece >= 0)) &&
                  !(spaces.axisymmetric() && !r.axisymmetric());
    if (r.kind != PointKind::volume)
      {
        Tensor<1, dim> na;
        for (unsigned int d = 0; d < dim; ++d)
          na[d] = props[Layout::normal_area_n + d];
        r.measure = na.norm();
        r.normal  = na / r.measure;
        if (r.piece >= 0)
          {
            // A roller or a tangential constraint acts along the wall the surface started
            // on: the directions come from the reference normal N_0 and apply to the total
            // displacement. With the current normal N_n instead, a tilt of the surface by
            // round-off turns part of the accumulated displacement into a lateral gap, and
            // the correction tilts the surface further: a growing mode (doc/method.md).
            Tensor<1, dim> na0;
            for (unsigned int d = 0; d < dim; ++d)
              na0[d] = props[Layout::normal_area_0 + d];
            r.projector =
              constraint_projector<dim>(boundary_conditions.piece(r.piece).displacement_condition,
                                        na0 / na0.norm());
          }
      }
    return r;
  }


  template <int dim>
  unsigned int
  PointCache<dim>::cell_of_point(const PointRecord<dim> &r) const
  {
    // A surface point may sit in a cell without volume points; it belongs to the active cell
    // next to it, whose extended functions reach it.
    const unsigned int cell = (r.kind == PointKind::volume) ? spaces.u_space().cell_containing(r.x)
                                                            : spaces.active_u_cell_containing(r.x);
    if (cell == dealii::numbers::invalid_unsigned_int)
      throw std::runtime_error("the surface point at " + format_point(r.x) +
                               " lies in no background cell that holds volume points; the "
                               "surface has separated from the bulk");
    return cell;
  }


  template <int dim>
  std::pair<unsigned int, unsigned int>
  PointCache<dim>::cell_and_piece_of_point(const PointRecord<dim> &r) const
  {
    const unsigned int cell = cell_of_point(r);
    if (!spaces.refined())
      return {cell, 0u};
    const auto        &u     = spaces.u();
    const unsigned int piece = u.piece_containing(r.x, cell);
    if (r.kind == PointKind::volume || leaf_classification_[u.leaf_of_piece(cell, piece)])
      return {cell, piece};

    // A surface point in a leaf without volume points: the leaf's extended functions lack
    // those of its control points outside the body, so they do not sum to one there, and the
    // point's increments were wrong (on a film refined at its top, the surface points' J fell
    // from 2.1 to 0.83 while the volume points beside them swelled). Evaluate it in the
    // nearest leaf with volume points, whose polynomial continues the field there, as a cell
    // without volume points does on a uniform grid (DiscreteSpaces::active_u_cell_containing).
    // First the leaf half a leaf inwards along the normal: the leaves beside it are often cut
    // slivers too, whose polynomial extrapolates the field poorly (a sideways neighbour made
    // the film's dip points lose 8-12 % of J per step).
    if (const auto inward = material_leaf_inwards(r, cell, piece))
      return *inward;
    return nearest_material_leaf(r, cell, piece);
  }


  template <int dim>
  std::optional<std::pair<unsigned int, unsigned int>>
  PointCache<dim>::material_leaf_inwards(const PointRecord<dim> &r,
                                         const unsigned int      cell,
                                         const unsigned int      piece) const
  {
    const auto        &u          = spaces.u();
    const auto        &space      = spaces.u_space();
    const auto        &hierarchy  = spaces.u_hierarchy();
    const unsigned int home_level = hierarchy.leaf_cell(u.leaf_of_piece(cell, piece)).level;
    const double       step       = 0.5 * hierarchy.level_space(home_level).cell_size(0);
    dealii::Point<dim> inward     = r.x;
    for (unsigned int d = 0; d < dim; ++d)
      {
        inward[d] -= step * r.normal[d];
        if (inward[d] < space.basis_1d(d).x_min() || inward[d] > space.basis_1d(d).x_max())
          return std::nullopt;
      }
    const unsigned int c = space.cell_containing(inward);
    if (!classification_[c])
      return std::nullopt;
    const unsigned int k = u.piece_containing(inward, c);
    if (!leaf_classification_[u.leaf_of_piece(c, k)])
      return std::nullopt;
    return std::make_pair(c, k);
  }


  template <int dim>
  std::pair<unsigned int, unsigned int>
  PointCache<dim>::nearest_material_leaf(const PointRecord<dim> &r,
                                         const unsigned int      cell,
                                         const unsigned int      piece) const
  {
    const auto  &u         = spaces.u();
    const auto  &space     = spaces.u_space();
    const auto  &hierarchy = spaces.u_hierarchy();
    const auto   home      = space.cell_multi_index(cell);
    double       best_gap  = std::numeric_limits<double>::max();
    unsigned int best_cell = cell, best_piece = piece;
    for (unsigned int neighbour = 0; neighbour < std::pow(3, dim); ++neighbour)
      {
        std::array<unsigned int, dim> index;
        bool                          valid = true;
        unsigned int                  rest  = neighbour;
        for (unsigned int d = 0; d < dim; ++d)
          {
            const int i = static_cast<int>(home[d]) + static_cast<int>(rest % 3) - 1;
            rest /= 3;
            valid &= i >= 0 && i < static_cast<int>(space.n_cells_per_direction()[d]);
            index[d] = valid ? i : 0;
          }
        if (!valid)
          continue;
        const unsigned int c = space.cell_index(index);
        if (!classification_[c])
          continue;
        for (unsigned int k = 0; k < u.n_pieces(c); ++k)
          {
            const unsigned int leaf = u.leaf_of_piece(c, k);
            if (!leaf_classification_[leaf])
              continue;
            const auto &[level, leaf_cell] = hierarchy.leaf_cell(leaf);
            const auto &level_space        = hierarchy.level_space(level);
            const auto  leaf_index         = level_space.cell_multi_index(leaf_cell);
            double      gap                = 0.;
            for (unsigned int d = 0; d < dim; ++d)
              {
                const double h     = level_space.cell_size(d);
                const double lower = level_space.basis_1d(d).x_min() + leaf_index[d] * h;
                const double out   = std::max({0., lower - r.x[d], r.x[d] - (lower + h)});
                gap += out * out;
              }
            if (gap < best_gap)
              {
                best_gap   = gap;
                best_cell  = c;
                best_piece = k;
              }
          }
      }
    return {best_cell, best_piece};
  }


  template <int dim>
  void
  PointCache<dim>::group_points(const std::vector<PointRecord<dim>>  &unsorted,
                                const std::vector<particle_iterator> &its,
                                const std::vector<unsigned int>      &cells,
                                const std::vector<unsigned int>      &pieces,
                                const std::vector<unsigned int>      &sides)
  {
    // Stable: within a cell the points keep the handler's order, so that sums over them (and
    // with them the results) do not depend on the sort.
    // On a refined grid a cell's points are grouped further by the leaf (piece) they use.
    std::vector<unsigned int> order(unsorted.size());
    std::iota(order.begin(), order.end(), 0u);
    const auto side = [&sides](const unsigned int i) {
      return sides.empty() ? 0u : sides[i];
    };
    std::stable_sort(order.begin(), order.end(), [&](const unsigned int a, const unsigned int b) {
      return std::make_tuple(cells[a], pieces[a], side(a)) <
             std::make_tuple(cells[b], pieces[b], side(b));
    });

    const auto own_list = [&](const unsigned int i) {
      return side(i) == 0 ? -1 : side_lists_.at({cells[i], pieces[i], side(i)});
    };
    order_ = order;
    points_.clear();
    particles_.clear();
    blocks_.clear();
    points_.reserve(order.size());
    particles_.reserve(order.size());
    unsigned int n_u_shapes = 0, n_mu_shapes = 0;
    for (const unsigned int i : order)
      {
        const unsigned int cell = cells[i];
        if (blocks_.empty() || blocks_.back().u_cell != cell ||
            blocks_.back().u_piece != pieces[i] || blocks_.back().own_u_dofs != own_list(i))
          {
            blocks_.push_back(new_block(cell, pieces[i], points_.size()));
            blocks_.back().own_u_dofs = own_list(i);
          }
        PointRecord<dim> r = unsorted[i];
        r.block            = blocks_.size() - 1;
        r.level            = blocks_.back().level;
        r.u_offset         = n_u_shapes;
        r.mu_offset        = n_mu_shapes;
        n_u_shapes += u_dofs(blocks_.back()).size();
        n_mu_shapes += mu_dofs(blocks_.back()).size();
        points_.push_back(r);
        particles_.push_back(its[i]);
        blocks_.back().end = points_.size();
      }
    u_values.resize(n_u_shapes);
    u_gradients.resize(n_u_shapes);
    mu_values.resize(n_mu_shapes);
    mu_gradients.resize(n_mu_shapes);
  }


  template <int dim>
  PointBlock
  PointCache<dim>::new_block(const unsigned int u_cell,
                             const unsigned int u_piece,
                             const unsigned int first) const
  {
    PointBlock block{u_cell, spaces.mu_cell_of(u_cell), first, first};
    block.u_piece = u_piece;
    if (spaces.refined())
      {
        // mu is one level coarser everywhere: the mu leaf that holds the u leaf's centre holds
        // all of it.
        const auto &hierarchy     = spaces.u_hierarchy();
        const auto &[level, leaf] = hierarchy.leaf_cell(spaces.u().leaf_of_piece(u_cell, u_piece));
        block.level               = level;
        const auto        &space  = hierarchy.level_space(level);
        const auto         index  = space.cell_multi_index(leaf);
        dealii::Point<dim> centre;
        for (unsigned int d = 0; d < dim; ++d)
          centre[d] = space.basis_1d(d).x_min() + (index[d] + 0.5) * space.cell_size(d);
        block.mu_piece = spaces.mu().piece_containing(centre, block.mu_cell);
      }
    return block;
  }


  template <int dim>
  void
  PointCache<dim>::evaluate_shape_functions()
  {
    // Every point writes its own ranges of the arrays: evaluate them in parallel.
    dealii::parallel::apply_to_subranges(
      0u,
      static_cast<unsigned int>(points_.size()),
      [this](const unsigned int begin, const unsigned int end) {
        std::vector<double>         values, scratch_values;
        std::vector<Tensor<1, dim>> gradients, scratch_gradients;
        for (unsigned int p = begin; p < end; ++p)
          {
            const PointRecord<dim> &r = points_[p];
            const PointBlock       &b = blocks_[r.block];
            for (const auto *space : {&spaces.u(), &spaces.mu()})
              {
                const bool         is_u  = (space == &spaces.u());
                const unsigned int cell  = is_u ? b.u_cell : b.mu_cell;
                const unsigned int piece = is_u ? b.u_piece : b.mu_piece;
                const unsigned int n     = space->cell_dofs(cell, piece).size();
                values.resize(n);
                gradients.resize(n);
                scratch_values.resize(space->space().functions_per_cell());
                scratch_gradients.resize(space->space().functions_per_cell());
                space->evaluate(r.x,
                                cell,
                                piece,
                                values,
                                gradients,
                                scratch_values,
                                scratch_gradients);
                const unsigned int offset = is_u ? r.u_offset : r.mu_offset;
                std::copy(values.begin(),
                          values.end(),
                          (is_u ? u_values : mu_values).begin() + offset);
                std::copy(gradients.begin(),
                          gradients.end(),
                          (is_u ? u_gradients : mu_gradients).begin() + offset);
              }
          }
      },
      256);
  }


  template <int dim>
  void
  PointCache<dim>::unknowns_of_block(const PointBlock                             &block,
                                     std::vector<dealii::types::global_dof_index> &dofs) const
  {
    const unsigned int n_u = spaces.n_u_dofs();
    dofs.clear();
    for (const unsigned int i : u_dofs(block))
      for (unsigned int c = 0; c < dim; ++c)
        dofs.push_back(dim * i + c);
    for (const unsigned int j : mu_dofs(block))
      dofs.push_back(n_u + j);
    std::sort(dofs.begin(), dofs.end());
  }


  template <int dim>
  void
  PointCache<dim>::unknowns_of_cell(const unsigned int                            u_cell,
                                    std::vector<dealii::types::global_dof_index> &dofs) const
  {
    // All pieces of the cell (a pair term couples whole cells) and every copy its blocks use.
    std::vector<unsigned int> u_dofs = spaces.u().cell_dofs(u_cell);
    const auto                first  = std::lower_bound(blocks_.begin(),
                                        blocks_.end(),
                                        u_cell,
                                        [](const PointBlock &b, const unsigned int c) {
                                          return b.u_cell < c;
                                        });
    for (auto b = first; b != blocks_.end() && b->u_cell == u_cell; ++b)
      if (b->own_u_dofs >= 0)
        u_dofs.insert(u_dofs.end(),
                      own_u_dofs_[b->own_u_dofs].begin(),
                      own_u_dofs_[b->own_u_dofs].end());
    std::sort(u_dofs.begin(), u_dofs.end());
    u_dofs.erase(std::unique(u_dofs.begin(), u_dofs.end()), u_dofs.end());
    const unsigned int n_u = spaces.n_u_dofs();
    dofs.clear();
    for (const unsigned int i : u_dofs)
      for (unsigned int c = 0; c < dim; ++c)
        dofs.push_back(dim * i + c);
    for (const unsigned int j : spaces.mu().cell_dofs(spaces.mu_cell_of(u_cell)))
      dofs.push_back(n_u + j);
    std::sort(dofs.begin(), dofs.end());
  }


  template <int dim>
  typename PointCache<dim>::Fields
  PointCache<dim>::fields_at(const PointRecord<dim>       &r,
                             const dealii::Vector<double> &solution) const
  {
    Fields fields;
    auto &[du, delta_F, mu]  = fields;
    const PointBlock &b      = blocks_[r.block];
    const auto       &u_dofs = this->u_dofs(b);
    const auto       &m_dofs = mu_dofs(b);
    const auto        n_u    = spaces.n_u_dofs();
    delta_F                  = dealii::unit_symmetric_tensor<dim>();
    du                       = Tensor<1, dim>();
    for (unsigned int a = 0; a < u_dofs.size(); ++a)
      {
        Tensor<1, dim> coefficient;
        for (unsigned int c = 0; c < dim; ++c)
          coefficient[c] = solution(dim * u_dofs[a] + c);
        delta_F += outer(coefficient, u_gradients[r.u_offset + a]);
        du += u_values[r.u_offset + a] * coefficient;
      }
    mu = 0.;
    for (unsigned int j = 0; j < m_dofs.size(); ++j)
      mu += mu_values[r.mu_offset + j] * solution(n_u + m_dofs[j]);
    return fields;
  }


  template class PointCache<2>;
  template class PointCache<3>;
} // namespace GelMPM
