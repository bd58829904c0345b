// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_SMOOTHED_AGGREGATION_PRECONDITIONER_H
#define CGAL_PROGRESSIVE_EMBEDDING_SMOOTHED_AGGREGATION_PRECONDITIONER_H

/// \file Smoothed_aggregation_preconditioner.h
/// An algebraic multigrid preconditioner for Eigen's conjugate gradients: `Smoothed_aggregation_preconditioner`.

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {

/// \ingroup PkgProgressiveEmbeddingSolvers
///
/// A smoothed-aggregation algebraic multigrid V-cycle (Vanek, Mandel and Brezina, 1996), as the preconditioner
/// of `Eigen::ConjugateGradient` for the symmetric positive definite systems of Tutte maps with symmetric weights
/// (uniform weights): `CGAL::Eigen_solver_traits<Eigen::ConjugateGradient<Eigen::SparseMatrix<double>,
/// Eigen::Lower | Eigen::Upper, Smoothed_aggregation_preconditioner<double> > >` is a model of
/// `SparseLinearAlgebraWithFactorTraits_d` for the named parameter `sparse_linear_solver` of `tutte_embedding()`.
/// Its cost grows linearly with the unknowns, where a sparse Cholesky factorization of a planar mesh's system
/// grows as their power 1.5 (`benchmark/results/large_meshes.md` compares them). The solution is that of the
/// conjugate gradients' tolerance (`setTolerance()`, a relative residual), not of a direct solve: the map is
/// certified (and repaired if needed) like any other.
///
/// Each level groups the unknowns into aggregates over the strong connections (\f$ |a_{ij}| \geq 0.08
/// \sqrt{a_{ii} a_{jj}} \f$: an unknown whose strong neighbours are all free starts one with them; the others join
/// the neighbouring aggregate they are most strongly connected to), smooths the piecewise
/// constant prolongation by one damped Jacobi step (damping \f$ 4/(3\rho) \f$, \f$ \rho \f$ the spectral radius of
/// \f$ D^{-1}A \f$ estimated by power iterations), and takes the Galerkin product \f$ P^T A P \f$ as the next level's
/// matrix, until at most `coarse_size` unknowns are left, which Eigen's `SimplicialLDLT` solves directly. The
/// V-cycle smooths by forward Gauss-Seidel sweeps before the coarse correction and backward ones after, so the
/// preconditioner is symmetric positive definite, as the conjugate gradients need. Everything is deterministic.
///
/// \tparam Scalar a floating-point type (`double`)
///
/// The matrix given to `compute()` must be stored whole (both triangles), as `Eigen::Lower | Eigen::Upper` has the
/// conjugate gradients use it, with a positive diagonal.
template <typename Scalar = double>
class Smoothed_aggregation_preconditioner
{
public:
  /// the sparse matrix type of the levels
  typedef Eigen::SparseMatrix<Scalar> Matrix;
  /// the vector type
  typedef Eigen::Matrix<Scalar, Eigen::Dynamic, 1> Vector;
  /// Eigen's index type
  typedef Eigen::Index Index;

  /// an empty preconditioner; `compute()` sets it up
  Smoothed_aggregation_preconditioner() { }

  /// sets the preconditioner up for `A`
  template <typename MatrixType>
  explicit Smoothed_aggregation_preconditioner(const MatrixType& A) { compute(A); }

  /// the largest number of unknowns solved directly at the coarsest level (default 4000)
  void set_coarse_size(std::size_t n) { m_coarse_size = (std::max)(std::size_t(1), n); }
  /// the Gauss-Seidel sweeps before and after each coarse correction (default 1)
  void set_smoothing_sweeps(int k) { m_sweeps = (std::max)(1, k); }

  /// the number of levels, the coarsest (solved directly) included
  std::size_t number_of_levels() const { return m_levels.size() + 1; }
  /// the number of unknowns of level `l` (0: the matrix given)
  Index level_size(std::size_t l) const { return l < m_levels.size() ? m_levels[l].A.rows() : m_coarse_rows; }

  /// nothing: the setup needs the values
  template <typename MatrixType>
  Smoothed_aggregation_preconditioner& analyzePattern(const MatrixType&) { return *this; }

  /// builds the levels for `A`
  template <typename MatrixType>
  Smoothed_aggregation_preconditioner& factorize(const MatrixType& A) { return compute(A); }

  /// builds the levels for `A`
  template <typename MatrixType>
  Smoothed_aggregation_preconditioner& compute(const MatrixType& A)
  {
    m_levels.clear();
    m_info = Eigen::Success;
    Matrix current = A;
    current.makeCompressed();
    while(static_cast<std::size_t>(current.rows()) > m_coarse_size && m_levels.size() < max_levels)
    {
      Level level;
      level.A = current;
      level.inverse_diagonal = current.diagonal();
      for(Index i = 0; i < current.rows(); ++i)
      {
        if(!(level.inverse_diagonal[i] > 0)) { m_info = Eigen::NumericalIssue; return *this; }
        level.inverse_diagonal[i] = Scalar(1) / level.inverse_diagonal[i];
      }
      Index aggregates = 0;
      const std::vector<Index> aggregate = aggregation(current, aggregates);
      if(aggregates >= current.rows()) break; // nothing coarsens: solve this level directly
      smoothed_prolongation(level, aggregate, aggregates);
      const Matrix AP = current * level.P;
      current = Matrix(level.R * AP);
      current.prune(Scalar(0));
      m_levels.push_back(std::move(level));
    }
    m_coarse_rows = current.rows();
    m_coarse.compute(current);
    if(m_coarse.info() != Eigen::Success) m_info = m_coarse.info();
    return *this;
  }

  /// one V-cycle applied to `b`
  template <typename Rhs>
  Vector solve(const Eigen::MatrixBase<Rhs>& b) const
  {
    Vector x;
    v_cycle(0, Vector(b), x);
    return x;
  }

  /// `Eigen::Success` once set up, else why not (a non-positive diagonal entry, a coarse matrix LDLT refused)
  Eigen::ComputationInfo info() const { return m_info; }

private:
  struct Level
  {
    Matrix A, P, R;
    Vector inverse_diagonal;
  };

  static constexpr std::size_t max_levels = 25;

  // Aggregates of the unknowns over the strong connections: j is strongly connected to i when
  // |a_ij| >= theta sqrt(a_ii a_jj) (theta = 0.08; the Galerkin matrices of the coarser levels have many weak
  // entries, which would make aggregates too large). First pass: an unknown whose strong neighbours are all free
  // starts an aggregate with them. Second: the others join the aggregate of their strongest neighbour aggregated in
  // the first pass. An unknown with none gets its own.
  static std::vector<Index> aggregation(const Matrix& A, Index& count)
  {
    const Index n = A.rows();
    const Scalar theta = Scalar(0.08);
    Vector diagonal = A.diagonal();
    auto strong = [&](Index i, Index j, Scalar a) {
      return j != i && std::abs(a) >= theta * std::sqrt(std::abs(diagonal[i] * diagonal[j]));
    };
    std::vector<Index> first(static_cast<std::size_t>(n), -1);
    count = 0;
    for(Index i = 0; i < n; ++i)
    {
      if(first[std::size_t(i)] >= 0) continue;
      bool free = true;
      for(typename Matrix::InnerIterator it(A, i); it && free; ++it)
        if(strong(i, it.row(), it.value()) && first[std::size_t(it.row())] >= 0) free = false;
      if(!free) continue;
      first[std::size_t(i)] = count;
      for(typename Matrix::InnerIterator it(A, i); it; ++it)
        if(strong(i, it.row(), it.value())) first[std::size_t(it.row())] = count;
      ++count;
    }
    std::vector<Index> result = first;
    for(Index i = 0; i < n; ++i)
    {
      if(first[std::size_t(i)] >= 0) continue;
      Scalar best = 0;
      for(typename Matrix::InnerIterator it(A, i); it; ++it)
      {
        const Index j = it.row();
        if(strong(i, j, it.value()) && first[std::size_t(j)] >= 0 && std::abs(it.value()) > best)
        {
          best = std::abs(it.value());
          result[std::size_t(i)] = first[std::size_t(j)];
        }
      }
      if(result[std::size_t(i)] < 0) result[std::size_t(i)] = count++;
    }
    return result;
  }

  // P = (I - w D^-1 A) P0, P0 the aggregates' indicator columns, w = 4 / (3 rho(D^-1 A)); R = P^T
  void smoothed_prolongation(Level& level, const std::vector<Index>& aggregate, Index aggregates) const
  {
    const Matrix& A = level.A;
    const Index n = A.rows();
    std::vector<Eigen::Triplet<Scalar> > t;
    t.reserve(static_cast<std::size_t>(n));
    for(Index i = 0; i < n; ++i) t.emplace_back(i, aggregate[std::size_t(i)], Scalar(1));
    Matrix P0(n, aggregates);
    P0.setFromTriplets(t.begin(), t.end());
    std::vector<Eigen::Triplet<Scalar> >().swap(t);
    const Matrix DA = level.inverse_diagonal.asDiagonal() * A;
    const Scalar w = Scalar(4) / (Scalar(3) * spectral_radius(DA));
    level.P = Matrix(P0 - w * Matrix(DA * P0));
    level.P.prune(Scalar(0));
    level.R = level.P.transpose();
  }

  // rho(M) from below by power iterations from a fixed pseudo-random start, raised by 5% (the damping needs an
  // upper estimate; the iterations converge from below)
  static Scalar spectral_radius(const Matrix& M)
  {
    const Index n = M.rows();
    Vector q(n);
    std::uint64_t s = 0x9E3779B97F4A7C15ull;
    for(Index i = 0; i < n; ++i)
    {
      s ^= s << 13; s ^= s >> 7; s ^= s << 17;
      q[i] = Scalar(double(s >> 11) / 9007199254740992.0 - 0.5);
    }
    Scalar rho = 0;
    for(int k = 0; k < 15; ++k)
    {
      const Scalar norm = q.norm();
      if(!(norm > 0)) break;
      Vector y = M * (q / norm);
      rho = y.norm();
      q.swap(y);
    }
    return rho > 0 ? Scalar(1.05) * rho : Scalar(2);
  }

  // one Gauss-Seidel sweep on A x = b, forward or backward (column i of the symmetric matrix is its row i)
  static void gauss_seidel(const Level& level, const Vector& b, Vector& x, bool forward)
  {
    const Index n = level.A.rows();
    for(Index k = 0; k < n; ++k)
    {
      const Index i = forward ? k : n - 1 - k;
      Scalar s = b[i];
      for(typename Matrix::InnerIterator it(level.A, i); it; ++it)
        if(it.row() != i) s -= it.value() * x[it.row()];
      x[i] = s * level.inverse_diagonal[i];
    }
  }

  void v_cycle(std::size_t l, const Vector& b, Vector& x) const
  {
    if(l == m_levels.size()) { x = m_coarse.solve(b); return; }
    const Level& level = m_levels[l];
    x = Vector::Zero(b.size());
    for(int k = 0; k < m_sweeps; ++k) gauss_seidel(level, b, x, true);
    const Vector coarse_b = level.R * (b - level.A * x);
    Vector coarse_x;
    v_cycle(l + 1, coarse_b, coarse_x);
    x += level.P * coarse_x;
    for(int k = 0; k < m_sweeps; ++k) gauss_seidel(level, b, x, false);
  }

  std::vector<Level> m_levels;
  Eigen::SimplicialLDLT<Matrix> m_coarse;
  Index m_coarse_rows = 0;
  std::size_t m_coarse_size = 4000;
  int m_sweeps = 1;
  Eigen::ComputationInfo m_info = Eigen::Success;
};

} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_SMOOTHED_AGGREGATION_PRECONDITIONER_H
