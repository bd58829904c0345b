// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_BLOCK_CG_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_BLOCK_CG_H

// Block_cg<ConcurrencyTag>: conjugate gradients with a Jacobi preconditioner for the optimizer's
// Newton systems on large meshes (a symmetric matrix of 2x2 blocks, one per pair of free vertices
// sharing a face). What Eigen's ConjugateGradient does not do:
//  - the matrix is kept as 2x2 blocks in single precision: the product is bound by memory bandwidth
//    and takes 20 bytes per block instead of 48 for double entries with their row indices; the
//    vectors, the dot products and the preconditioner stay in double. The step needs only a rough
//    solve (200 iterations end far above any tolerance at 100k vertices and more; the line search
//    decides), so the rounding of the matrix to float changes nothing that matters;
//  - with CGAL::Parallel_tag (and TBB) the passes run over fixed chunks of rows, whose partial sums
//    are added in chunk order: the result is the same bit for bit on any number of threads, and the
//    same as with CGAL::Sequential_tag.
// The input is the optimizer's column-major matrix: columns 2j and 2j + 1 hold the same rows, in
// pairs 2i, 2i + 1 (build_pattern() in distortion_optimizer.h), and the matrix is symmetric.

#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#endif

#include <Eigen/Core>
#include <Eigen/Sparse>

#include <array>
#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

template <class ConcurrencyTag>
class Block_cg
{
public:
  typedef Eigen::SparseMatrix<double> SpMat;
  static constexpr std::size_t chunk_rows = 4096; // block rows per chunk (the unit of work and of summation)

  // the block structure of H (its pattern must not change afterwards)
  void set_pattern(const SpMat& H)
  {
    n_ = std::size_t(H.cols() / 2);
    start_.assign(n_ + 1, 0);
    col_.clear();
    const int* outer = H.outerIndexPtr();
    const int* inner = H.innerIndexPtr();
    for(std::size_t j = 0; j < n_; ++j)
    {
      for(int k = outer[2 * j]; k < outer[2 * j + 1]; k += 2) col_.push_back(inner[k] / 2);
      start_[j + 1] = col_.size();
    }
    val_.resize(col_.size());
    dinv_.resize(2 * n_);
  }

  // the values of H (same pattern), rounded to float, and the inverse of its diagonal
  void set_values(const SpMat& H)
  {
    const int* outer = H.outerIndexPtr();
    const double* v = H.valuePtr();
    for_chunks([&](std::size_t begin, std::size_t end) {
      for(std::size_t j = begin; j < end; ++j)
      {
        // block (j, i) element (a, b) is H(2j + a, 2i + b) = H(2i + b, 2j + a) (symmetry): in column 2j + a
        const int c0 = outer[2 * j], len = outer[2 * j + 1] - outer[2 * j];
        for(std::size_t k = start_[j]; k < start_[j + 1]; ++k)
        {
          const int at = c0 + 2 * int(k - start_[j]);
          val_[k] = {{ float(v[at]), float(v[at + 1]), float(v[at + len]), float(v[at + len + 1]) }};
          if(col_[k] == int(j)) { dinv_[2 * j] = 1. / v[at]; dinv_[2 * j + 1] = 1. / v[at + len + 1]; }
        }
      }
      return 0.;
    });
  }

  // x ~ H^-1 b, starting from 0; returns the number of iterations. error(): |b - H x| / |b|.
  int solve(const Eigen::VectorXd& b, Eigen::VectorXd& x, int max_iterations, double tolerance)
  {
    const std::size_t m = 2 * n_;
    x = Eigen::VectorXd::Zero(Eigen::Index(m));
    r_ = b;
    p_.resize(Eigen::Index(m));
    q_.resize(Eigen::Index(m));
    const double bb = for_chunks([&](std::size_t begin, std::size_t end) {
      double s = 0;
      for(std::size_t i = 2 * begin; i < 2 * end; ++i) { p_[i] = dinv_[i] * r_[i]; s += b[i] * b[i]; }
      return s;
    });
    error_ = 0;
    if(!(bb > 0)) return 0;
    double rz = for_chunks([&](std::size_t begin, std::size_t end) {
      double s = 0;
      for(std::size_t i = 2 * begin; i < 2 * end; ++i) s += r_[i] * p_[i];
      return s;
    });
    const double threshold = tolerance * tolerance * bb;
    double rr = bb;
    int it = 0;
    while(it < max_iterations)
    {
      // q = H p, and p.q
      const double pq = for_chunks([&](std::size_t begin, std::size_t end) {
        double s = 0;
        for(std::size_t j = begin; j < end; ++j)
        {
          double y0 = 0, y1 = 0;
          for(std::size_t k = start_[j]; k < start_[j + 1]; ++k)
          {
            const std::array<float, 4>& a = val_[k];
            const double p0 = p_[2 * col_[k]], p1 = p_[2 * col_[k] + 1];
            y0 += double(a[0]) * p0 + double(a[1]) * p1;
            y1 += double(a[2]) * p0 + double(a[3]) * p1;
          }
          q_[2 * j] = y0; q_[2 * j + 1] = y1;
          s += p_[2 * j] * y0 + p_[2 * j + 1] * y1;
        }
        return s;
      });
      if(!(pq > 0) || !std::isfinite(pq)) break; // not positive definite in float: keep what we have
      const double alpha = rz / pq;
      ++it;
      // x += alpha p, r -= alpha q, and r.r, r.z with z = D^-1 r
      rr = 0;
      const double rz_new = for_chunks2([&](std::size_t begin, std::size_t end, double& s_rr) {
        double s_rz = 0;
        for(std::size_t i = 2 * begin; i < 2 * end; ++i)
        {
          x[i] += alpha * p_[i];
          r_[i] -= alpha * q_[i];
          s_rr += r_[i] * r_[i];
          s_rz += r_[i] * r_[i] * dinv_[i];
        }
        return s_rz;
      }, rr);
      if(rr <= threshold) break;
      const double beta = rz_new / rz;
      rz = rz_new;
      for_chunks([&](std::size_t begin, std::size_t end) {
        for(std::size_t i = 2 * begin; i < 2 * end; ++i) p_[i] = dinv_[i] * r_[i] + beta * p_[i];
        return 0.;
      });
    }
    error_ = std::sqrt(rr / bb);
    return it;
  }

  double error() const { return error_; }

private:
  std::size_t number_of_chunks() const { return (n_ + chunk_rows - 1) / chunk_rows; }

  // body(begin, end) over the chunks of block rows; returns the sum of its results in chunk order
  template <class Body>
  double for_chunks(Body body)
  {
    double unused = 0;
    return for_chunks2([&](std::size_t b, std::size_t e, double&) { return body(b, e); }, unused);
  }

  // the same with a second sum, passed by reference to each chunk's body and added into `second`
  template <class Body>
  double for_chunks2(Body body, double& second)
  {
    const std::size_t nc = number_of_chunks();
    partial_.assign(2 * nc, 0.);
    auto run = [&](std::size_t c) {
      const std::size_t begin = c * chunk_rows, end = (std::min)(n_, begin + chunk_rows);
      partial_[2 * c] = body(begin, end, partial_[2 * c + 1]);
    };
#ifdef CGAL_LINKED_WITH_TBB
    if(std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value && nc > 1)
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nc, 1), [&](const tbb::blocked_range<std::size_t>& range) {
        for(std::size_t c = range.begin(); c != range.end(); ++c) run(c);
      }, tbb::simple_partitioner());
    else
#endif
      for(std::size_t c = 0; c < nc; ++c) run(c);
    double s = 0;
    for(std::size_t c = 0; c < nc; ++c) { s += partial_[2 * c]; second += partial_[2 * c + 1]; }
    return s;
  }

  std::size_t n_ = 0;                          // block rows (free vertices)
  std::vector<std::size_t> start_;             // per block row: its first block
  std::vector<int> col_;                       // per block: its block column
  std::vector<std::array<float, 4> > val_;     // per block: (0,0), (0,1), (1,0), (1,1)
  std::vector<double> dinv_;                   // inverse of the diagonal
  std::vector<double> partial_;                // per chunk: its partial sums
  Eigen::VectorXd r_, p_, q_;
  double error_ = 0;
};

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_BLOCK_CG_H
