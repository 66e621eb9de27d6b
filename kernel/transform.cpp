// Exact 4x4 homogeneous transforms, row-vector convention (see transform.hpp; course notes section 20).
#include "kernel/transform.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>
#include <vector>

namespace hlr {

std::optional<Axis> parse_axis(const std::string& s) {
  if (s.size() != 1) return std::nullopt;
  switch (std::tolower(static_cast<unsigned char>(s[0]))) {
    case 'x': return Axis::X;
    case 'y': return Axis::Y;
    case 'z': return Axis::Z;
  }
  return std::nullopt;
}

Matrix4 identity_transform() {
  Matrix4 m;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) m(i, j) = (i == j) ? 1 : 0;
  return m;
}

Matrix4 translation(const Vector3& d) {
  Matrix4 m = identity_transform();
  for (int j = 0; j < 3; ++j) m(3, j) = d[j];
  return m;
}

Matrix4 scaling(const Vector3& k, const Point3& c) {
  Matrix4 m = identity_transform();
  for (int j = 0; j < 3; ++j) {
    m(j, j) = k[j];
    m(3, j) = (1 - k[j]) * c[j];
  }
  return m;
}

Matrix4 rotation(Axis axis, const Rotation& r, const Point3& c) {
  // Indices (i, j) of the rotated plane: about OZ (x, y), about OX (y, z), about OY (z, x).
  int i = 0, j = 1;
  if (axis == Axis::X) {
    i = 1;
    j = 2;
  } else if (axis == Axis::Y) {
    i = 2;
    j = 0;
  }
  Matrix4 rot = identity_transform();
  rot(i, i) = r.cos;
  rot(i, j) = r.sin;
  rot(j, i) = -r.sin;
  rot(j, j) = r.cos;
  Vector3 minus_c(-c.x(), -c.y(), -c.z()), plus_c(c.x(), c.y(), c.z());
  return compose(compose(translation(minus_c), rot), translation(plus_c));
}

Matrix4 reflection(Axis axis, const Point3& c) {
  Rational k[3] = {1, 1, 1};
  k[static_cast<int>(axis)] = -1;
  return scaling(Vector3(k[0], k[1], k[2]), c);
}

Matrix4 perspective(const Rational& cx, const Rational& cy, const Rational& cz) {
  if (cx == 0 && cy == 0 && cz == 0)
    throw std::invalid_argument("perspective needs at least one non-zero centre distance");
  Matrix4 m = identity_transform();
  const Rational* c[3] = {&cx, &cy, &cz};
  for (int i = 0; i < 3; ++i)
    if (*c[i] != 0) m(i, 3) = -1 / *c[i];
  return m;
}

Matrix4 compose(const Matrix4& a, const Matrix4& b) {
  Matrix4 r;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      Rational s = 0;
      for (int k = 0; k < 4; ++k) s += a(i, k) * b(k, j);
      r(i, j) = s;
    }
  return r;
}

std::optional<Matrix4> inverse(const Matrix4& m) {
  Matrix4 a = m, inv = identity_transform();
  for (int col = 0; col < 4; ++col) {
    int piv = col;
    while (piv < 4 && a(piv, col) == 0) ++piv;
    if (piv == 4) return std::nullopt;
    if (piv != col) {
      a.swap_rows(piv, col);
      inv.swap_rows(piv, col);
    }
    Rational p = a(col, col);
    for (int j = 0; j < 4; ++j) {
      a(col, j) /= p;
      inv(col, j) /= p;
    }
    for (int r = 0; r < 4; ++r) {
      if (r == col || a(r, col) == 0) continue;
      Rational f = a(r, col);
      for (int j = 0; j < 4; ++j) {
        a(r, j) -= f * a(col, j);
        inv(r, j) -= f * inv(col, j);
      }
    }
  }
  return inv;
}

Point3 apply(const Matrix4& m, const Point3& p) {
  Rational out[4];
  for (int j = 0; j < 4; ++j) {
    Rational s = p.x() * m(0, j) + p.y() * m(1, j);
    s += p.z() * m(2, j);
    s += m(3, j);
    out[j] = s;
  }
  if (out[3] == 0)
    throw std::domain_error("point " + to_string(p) + " goes to infinity (w = 0)");
  if (out[3] == 1) return Point3(out[0], out[1], out[2]);
  return Point3(out[0] / out[3], out[1] / out[3], out[2] / out[3]);
}

Vector3 apply_to_direction(const Matrix4& m, const Vector3& v) {
  Rational out[3];
  for (int j = 0; j < 3; ++j) {
    Rational s = v.x() * m(0, j) + v.y() * m(1, j);
    s += v.z() * m(2, j);
    out[j] = s;
  }
  return Vector3(out[0], out[1], out[2]);
}

bool is_affine(const Matrix4& m) {
  return m(0, 3) == 0 && m(1, 3) == 0 && m(2, 3) == 0 && m(3, 3) == 1;
}

std::string to_string(const Matrix4& m) {
  std::vector<std::string> cells(16);
  std::size_t width = 1;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      cells[i * 4 + j] = to_string(m(i, j));
      width = std::max(width, cells[i * 4 + j].size());
    }
  std::string out;
  for (int i = 0; i < 4; ++i) {
    out += "[";
    for (int j = 0; j < 4; ++j) {
      const std::string& c = cells[i * 4 + j];
      out += std::string(width - c.size() + (j ? 1 : 0), ' ') + c;
    }
    out += "]\n";
  }
  return out;
}

}  // namespace hlr
