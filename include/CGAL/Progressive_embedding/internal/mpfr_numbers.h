// Copyright (c) 2026 Progressive_embedding contributors.
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
// Author(s) : Progressive_embedding contributors

#ifndef CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_MPFR_NUMBERS_H
#define CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_MPFR_NUMBERS_H

// A block of raw MPFR numbers of one precision, with their limbs in one allocation: the solvers'
// loops then run without an allocation per operation (CGAL::Gmpfr's operators allocate a
// reference-counted result for each, which costs far more than the operation at a few hundred bits).
// Every number starts at +0.

#include <CGAL/Gmpfr.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace Progressive_embedding {
namespace internal {

class Mpfr_numbers
{
  std::vector<__mpfr_struct> v_;
  std::vector<mp_limb_t> limbs_;
public:
  Mpfr_numbers(std::size_t count, mpfr_prec_t p)
    : v_(count), limbs_(count * (mpfr_custom_get_size(p) / sizeof(mp_limb_t)))
  {
    const std::size_t per = mpfr_custom_get_size(p) / sizeof(mp_limb_t);
    for(std::size_t i = 0; i < count; ++i)
      mpfr_custom_init_set(&v_[i], MPFR_ZERO_KIND, 0, p, limbs_.data() + i * per);
  }
  Mpfr_numbers(const Mpfr_numbers&) = delete;            // the numbers point into limbs_
  Mpfr_numbers& operator=(const Mpfr_numbers&) = delete;
  std::size_t size() const { return v_.size(); }
  mpfr_ptr operator[](std::size_t i) { return &v_[i]; }
  mpfr_srcptr operator[](std::size_t i) const { return &v_[i]; }
};

// a CGAL::Gmpfr of precision p holding x
inline CGAL::Gmpfr to_gmpfr(mpfr_srcptr x, mpfr_prec_t p)
{
  CGAL::Gmpfr a(0, static_cast<CGAL::Gmpfr::Precision_type>(p));
  mpfr_set(a.fr(), x, MPFR_RNDN);
  return a;
}

} // namespace internal
} // namespace Progressive_embedding
} // namespace CGAL

#endif // CGAL_PROGRESSIVE_EMBEDDING_INTERNAL_MPFR_NUMBERS_H
