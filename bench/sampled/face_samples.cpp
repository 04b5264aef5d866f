#include "bench/sampled/face_samples.h"

#include <algorithm>
#include <glm/geometric.hpp>
#include <limits>

namespace shadowgen::bench {

void face_samples(const ConvexFace& face, int k, std::vector<glm::dvec3>& out) {
  out.clear();
  const glm::dvec3 o = face.loop[0];
  const glm::dvec3 u = glm::normalize(face.loop[1] - o);
  const glm::dvec3 w = glm::cross(face.normal, u);
  double umin = std::numeric_limits<double>::infinity(), umax = -umin, wmin = umin, wmax = -umin;
  for (const glm::dvec3& v : face.loop) {
    const double a = glm::dot(v - o, u), b = glm::dot(v - o, w);
    umin = std::min(umin, a);
    umax = std::max(umax, a);
    wmin = std::min(wmin, b);
    wmax = std::max(wmax, b);
  }
  for (int i = 0; i < k; ++i) {
    for (int j = 0; j < k; ++j) {
      const glm::dvec3 p = o + (umin + (umax - umin) * (i + 0.5) / k) * u +
                           (wmin + (wmax - wmin) * (j + 0.5) / k) * w;
      bool inside = true;
      for (std::size_t m = 0, n = face.loop.size(); m < n && inside; ++m) {
        const glm::dvec3& a = face.loop[m];
        const glm::dvec3& b = face.loop[(m + 1) % n];
        inside = glm::dot(glm::cross(b - a, p - a), face.normal) >= 0.0;
      }
      if (inside) out.push_back(p);
    }
  }
}

}  // namespace shadowgen::bench
