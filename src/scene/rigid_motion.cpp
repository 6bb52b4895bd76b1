#include "scene/rigid_motion.h"

#include <array>
#include <cmath>

namespace lensrt {

std::optional<RTCQuaternionDecomposition> quaternionDecomposition(const Transform& xf) {
  const Transform::Matrix& m = xf.matrix();
  std::array<Vec3d, 3> a;
  for (int c = 0; c < 3; ++c) a[c] = {m[0][c], m[1][c], m[2][c]};
  // Gram-Schmidt on the columns: a_c = sum_r q_r u_rc with u upper triangular.
  const double u00 = length(a[0]);
  if (!(u00 > 0) || !std::isfinite(u00)) return std::nullopt;
  const Vec3d q0 = a[0] / u00;
  const double u01 = dot(q0, a[1]);
  const Vec3d v1 = a[1] - q0 * u01;
  const double u11 = length(v1);
  if (!(u11 > 1e-12 * u00)) return std::nullopt;
  const Vec3d q1 = v1 / u11;
  const double u02 = dot(q0, a[2]), u12 = dot(q1, a[2]);
  const Vec3d v2 = a[2] - q0 * u02 - q1 * u12;
  double u22 = length(v2);
  if (!(u22 > 1e-12 * std::max(u00, u11))) return std::nullopt;
  Vec3d q2 = v2 / u22;
  if (dot(cross(q0, q1), q2) < 0) {  // a mirror: R stays a rotation
    q2 = -q2;
    u22 = -u22;
  }
  // The rotation with columns q0, q1, q2 as a unit quaternion (Shepperd's
  // method: the largest of the four squares first, for accuracy).
  const double r00 = q0.x, r11 = q1.y, r22 = q2.z;
  const double r21 = q1.z, r12 = q2.y, r02 = q2.x, r20 = q0.z, r10 = q0.y, r01 = q1.x;
  double w, x, y, z;
  const double trace = r00 + r11 + r22;
  if (trace > 0) {
    const double s = 2 * std::sqrt(1 + trace);
    w = s / 4, x = (r21 - r12) / s, y = (r02 - r20) / s, z = (r10 - r01) / s;
  } else if (r00 > r11 && r00 > r22) {
    const double s = 2 * std::sqrt(1 + r00 - r11 - r22);
    w = (r21 - r12) / s, x = s / 4, y = (r01 + r10) / s, z = (r02 + r20) / s;
  } else if (r11 > r22) {
    const double s = 2 * std::sqrt(1 + r11 - r00 - r22);
    w = (r02 - r20) / s, x = (r01 + r10) / s, y = s / 4, z = (r12 + r21) / s;
  } else {
    const double s = 2 * std::sqrt(1 + r22 - r00 - r11);
    w = (r10 - r01) / s, x = (r02 + r20) / s, y = (r12 + r21) / s, z = s / 4;
  }
  RTCQuaternionDecomposition d;
  rtcInitQuaternionDecomposition(&d);
  rtcQuaternionDecompositionSetScale(&d, float(u00), float(u11), float(u22));
  rtcQuaternionDecompositionSetSkew(&d, float(u01), float(u02), float(u12));
  rtcQuaternionDecompositionSetQuaternion(&d, float(w), float(x), float(y), float(z));
  rtcQuaternionDecompositionSetTranslation(&d, float(m[0][3]), float(m[1][3]), float(m[2][3]));
  return d;
}

std::optional<std::vector<RTCQuaternionDecomposition>> rigidMotionSteps(const std::vector<Transform>& steps) {
  std::vector<RTCQuaternionDecomposition> out;
  for (const Transform& xf : steps) {
    std::optional<RTCQuaternionDecomposition> d = quaternionDecomposition(xf);
    if (!d) return std::nullopt;
    if (!out.empty()) {
      const RTCQuaternionDecomposition& p = out.back();
      if (p.quaternion_r * d->quaternion_r + p.quaternion_i * d->quaternion_i +
              p.quaternion_j * d->quaternion_j + p.quaternion_k * d->quaternion_k <
          0)
        rtcQuaternionDecompositionSetQuaternion(&*d, -d->quaternion_r, -d->quaternion_i, -d->quaternion_j,
                                                -d->quaternion_k);
    }
    out.push_back(*d);
  }
  return out;
}

}  // namespace lensrt
