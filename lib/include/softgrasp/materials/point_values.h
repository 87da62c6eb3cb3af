#ifndef softgrasp_materials_point_values_h
#define softgrasp_materials_point_values_h

#include <array>

namespace softgrasp
{
  /// Points per block of the vectorised stress path (a multiple of every
  /// SIMD width).
  inline constexpr unsigned int point_block_size = 64;

  /// One value per point of a block (structure of arrays).
  using PointValues = std::array<double, point_block_size>;
} // namespace softgrasp

#endif
