// GLSL's smoothstep on the C++ side (the studio's falloffs, the condensation's fades).
#pragma once

#include <algorithm>

namespace draught {

template <typename T>
T smoothstep(T e0, T e1, T x) {
  const T t = std::clamp((x - e0) / (e1 - e0), T(0), T(1));
  return t * t * (T(3) - T(2) * t);
}

}  // namespace draught
