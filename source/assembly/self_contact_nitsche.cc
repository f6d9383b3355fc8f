// Self-contact by Nitsche's method (SelfContactAssembler::nitsche_pair(), tractions()): the
// point's own traction, its derivatives and the segment normal's.
#include <gelmpm/assembly/axisymmetric_terms.h>
#include <gelmpm/assembly/displacement_nitsche.h>
#include <gelmpm/assembly/self_contact.h>

#include <deal.II/base/mpi.h>
#include <deal.II/lac/full_matrix.h>

#include <algorithm>

namespace GelMPM
{
  using dealii::Point;
  using dealii::Tensor;


  namespace
  {
    /**
     * The first and second derivatives of the normal of a pair's surface with respect to the
     * coordinates (x_s, x_a, x_b) of PairGap: first[i][k] = dn_i/dX_k, second[i][k][l]. In 3D
     * the normal is the point's at the start of the step: zero.
     */
    template <int dim>
    struct NormalDerivatives
    {
      double first[dim][3 * dim]           = {};
      double second[dim][3 * dim][3 * dim] = {};
    };


    NormalDerivatives<3>
    normal_derivatives(const Point<3> &, const Point<3> &)
    {
      return {};
    }


    /** A segment's unit normal n = R e / |e| (e = x_b - x_a, R the rotation by +90 degrees). */
    NormalDerivatives<2>
    normal_derivatives(const Point<2> &x_a, const Point<2> &x_b)
    {
      // With t = e / L: dn_i/de_j = (R_ij - n_i t_j) / L and
      // d2n_i/de_j de_k = (3 n_i t_j t_k - R_ij t_k - R_ik t_j - delta_jk n_i) / L^2.
      const Tensor<1, 2>   e = x_b - x_a;
      const double         L = e.norm();
      const Tensor<1, 2>   t = e / L;
      const Tensor<1, 2>   n({-t[1], t[0]});
      const double         R[2][2] = {{0., -1.}, {1., 0.}};
      const double         in_e[3] = {0., -1., 1.};
      NormalDerivatives<2> result;
      for (unsigned int i = 0; i < 2; ++i)
        for (unsigned int m = 0; m < 3; ++m)
          for (unsigned int j = 0; j < 2; ++j)
            {
              result.first[i][2 * m + j] = in_e[m] * (R[i][j] - n[i] * t[j]) / L;
              for (unsigned int l = 0; l < 3; ++l)
                for (unsigned int k = 0; k < 2; ++k)
                  result.second[i][2 * m + j][2 * l + k] =
                    in_e[m] * in_e[l] *
                    (3. * n[i] * t[j] * t[k] - R[i][j] * t[k] - R[i][k] * t[j] -
                     (j == k ? n[i] : 0.)) /
                    (L * L);
            }
      return result;
    }
  } // namespace


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
    const auto dn =
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


  template std::vector<Tensor<1, 2>>
  SelfContactAssembler<2>::tractions(const PointCache<2> &, const dealii::Vector<double> &) const;
  template std::vector<Tensor<1, 3>>
  SelfContactAssembler<3>::tractions(const PointCache<3> &, const dealii::Vector<double> &) const;
  template AssemblyCopy
  SelfContactAssembler<2>::nitsche_pair(const PointCache<2> &,
                                        const dealii::Vector<double> &,
                                        const Pair &,
                                        const PairGap<2> &,
                                        const bool) const;
  template AssemblyCopy
  SelfContactAssembler<3>::nitsche_pair(const PointCache<3> &,
                                        const dealii::Vector<double> &,
                                        const Pair &,
                                        const PairGap<3> &,
                                        const bool) const;
} // namespace GelMPM
