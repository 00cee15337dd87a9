// Half-precision (IEEE 754 binary16) limits shared by the writers that store half texels
// (EXR HALF, KTX2/DDS R16*_SFLOAT, the engine modules).
#pragma once

namespace kiln {

/// The largest finite half float.
constexpr float kHalfMax = 65504.0f;

}  // namespace kiln
