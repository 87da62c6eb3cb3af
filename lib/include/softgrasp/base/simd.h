#ifndef softgrasp_base_simd_h
#define softgrasp_base_simd_h

// GCC 12 warns of an uninitialized variable inside its own AVX-512
// intrinsics (_mm512_undefined_pd in _mm512_sqrt_pd, GCC bug 105593) when
// they are inlined into user code; the intrinsics are correct.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif
#include <experimental/simd>
#pragma GCC diagnostic pop

namespace softgrasp
{
  /**
   * Explicit SIMD of the vectorised stress kernel, independent of how
   * deal.II was configured: the C++ Parallelism TS 2 type of the toolchain
   * (std::experimental::simd, libstdc++ since GCC 11) at the widest width
   * that the compiler flags allow (8 doubles with AVX-512, 4 with AVX2, 2
   * with the x86-64 baseline).
   *
   * The type is used inside function bodies only, never in an interface:
   * data crosses between translation units as plain double arrays
   * (PointValues), so that code built with other flags than the library
   * (a consumer's own model, say) stays compatible.
   */
  namespace simd
  {
    namespace stdx = std::experimental;

    /// A SIMD register of doubles.
    using Double = stdx::native_simd<double>;

    /// Lanes of Double.
    inline constexpr unsigned int width = Double::size();

    /// Lanes of the widest Double of any flags: arrays handed to SIMD code
    /// are padded to a multiple of this.
    inline constexpr unsigned int max_width = 8;

    /// Load width values from @p p (no alignment required).
    inline Double load(const double *p)
    {
      return Double(p, stdx::element_aligned);
    }

    /// Store @p v to width values at @p p.
    inline void store(const Double &v, double *p)
    {
      v.copy_to(p, stdx::element_aligned);
    }
  } // namespace simd
} // namespace softgrasp

#endif
