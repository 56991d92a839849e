// Copyright 2026 the brdfbake authors.
// SPDX-License-Identifier: Apache-2.0
//
// A small 3-vector value type and the shading-frame helpers every model uses.
// Convention (docs/format.md): local frame with n = +z, directions point
// away from the surface, mu = cos(theta) = w.z.

#ifndef BRDFBAKE_MODELS_VEC3_H_
#define BRDFBAKE_MODELS_VEC3_H_

#include <cmath>

#include "brdfbake/models/constants.h"

namespace brdfbake {

template <typename T>
struct Vec3 {
  T x = 0, y = 0, z = 0;

  constexpr Vec3() = default;
  constexpr Vec3(T x_, T y_, T z_) : x(x_), y(y_), z(z_) {}
  template <typename U>
  constexpr explicit Vec3(const Vec3<U>& v)
      : x(static_cast<T>(v.x)), y(static_cast<T>(v.y)), z(static_cast<T>(v.z)) {}

  constexpr Vec3 operator+(const Vec3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  constexpr Vec3 operator-(const Vec3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  constexpr Vec3 operator-() const { return {-x, -y, -z}; }
  constexpr Vec3 operator*(T s) const { return {x * s, y * s, z * s}; }
  constexpr Vec3 operator/(T s) const { return {x / s, y / s, z / s}; }
  T operator[](int i) const { return i == 0 ? x : (i == 1 ? y : z); }
};

template <typename T>
constexpr Vec3<T> operator*(T s, const Vec3<T>& v) {
  return v * s;
}

template <typename T>
constexpr T Dot(const Vec3<T>& a, const Vec3<T>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

template <typename T>
constexpr Vec3<T> Cross(const Vec3<T>& a, const Vec3<T>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <typename T>
T Length(const Vec3<T>& v) {
  return std::sqrt(Dot(v, v));
}

// Returns v / |v|; the zero vector maps to itself (callers reject it first).
template <typename T>
Vec3<T> Normalize(const Vec3<T>& v) {
  const T len2 = Dot(v, v);
  if (!(len2 > T(0))) return v;
  return v / std::sqrt(len2);
}

// Unit direction from cos(theta) and azimuth phi.
template <typename T>
Vec3<T> FromMuPhi(T mu, T phi) {
  const T sin_theta = std::sqrt(std::fmax(T(0), (T(1) - mu) * (T(1) + mu)));
  return {sin_theta * std::cos(phi), sin_theta * std::sin(phi), mu};
}

// Mirror reflection of w about the unit normal m.
template <typename T>
Vec3<T> Reflect(const Vec3<T>& w, const Vec3<T>& m) {
  return m * (T(2) * Dot(w, m)) - w;
}

// A 3x3 matrix, row-major; used for the ellipsoid's A = S R and SEL's Q.
template <typename T>
struct Mat3 {
  T m[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};

  Vec3<T> operator*(const Vec3<T>& v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
            m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
  Mat3 operator*(const Mat3& o) const {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        r.m[i][j] = m[i][0] * o.m[0][j] + m[i][1] * o.m[1][j] + m[i][2] * o.m[2][j];
    return r;
  }
  Mat3 Transposed() const {
    Mat3 r;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.m[i][j] = m[j][i];
    return r;
  }
  T Determinant() const {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
           m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  }
  static Mat3 Diagonal(T a, T b, T c) {
    Mat3 r;
    r.m[0][0] = a;
    r.m[1][1] = b;
    r.m[2][2] = c;
    return r;
  }
  static Mat3 RotX(T t) {
    Mat3 r;
    const T c = std::cos(t), s = std::sin(t);
    r.m[1][1] = c; r.m[1][2] = -s;
    r.m[2][1] = s; r.m[2][2] = c;
    return r;
  }
  static Mat3 RotY(T t) {
    Mat3 r;
    const T c = std::cos(t), s = std::sin(t);
    r.m[0][0] = c; r.m[0][2] = s;
    r.m[2][0] = -s; r.m[2][2] = c;
    return r;
  }
  static Mat3 RotZ(T t) {
    Mat3 r;
    const T c = std::cos(t), s = std::sin(t);
    r.m[0][0] = c; r.m[0][1] = -s;
    r.m[1][0] = s; r.m[1][1] = c;
    return r;
  }
};

template <typename T>
inline constexpr T kSqrtPi = T(1.772453850905516027298167483341145182L);

}  // namespace brdfbake

#endif  // BRDFBAKE_MODELS_VEC3_H_
