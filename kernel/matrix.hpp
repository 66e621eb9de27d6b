// Small exact matrices for the course's homogeneous coordinates (section 20: a point
// is the row [x y z 1], a transform a 4x4 matrix, Roberts' body matrix 4 x n): rational
// entries, row-major, indexed m(i, j), filled with `m << a, b, c, d` row by row. Kept free of
// any linear-algebra library so that every header of the kernel stays light.
#pragma once

#include <utility>
#include <vector>

#include "kernel/number.hpp"

namespace hlr {

/// A rows x cols matrix of rationals, zero-initialised.
class RationalMatrix {
 public:
  RationalMatrix(int rows = 0, int cols = 0) : rows_(rows), cols_(cols), a_(static_cast<std::size_t>(rows) * cols) {}
  int rows() const { return rows_; }
  int cols() const { return cols_; }
  Rational& operator()(int i, int j) { return a_[static_cast<std::size_t>(i) * cols_ + j]; }
  const Rational& operator()(int i, int j) const { return a_[static_cast<std::size_t>(i) * cols_ + j]; }
  /// Resizes to rows x cols; entries become zero.
  void resize(int rows, int cols) {
    rows_ = rows;
    cols_ = cols;
    a_.assign(static_cast<std::size_t>(rows) * cols, Rational(0));
  }
  /// Column j as a list of rows() values.
  std::vector<Rational> col(int j) const {
    std::vector<Rational> c;
    c.reserve(rows_);
    for (int i = 0; i < rows_; ++i) c.push_back((*this)(i, j));
    return c;
  }
  void swap_rows(int r, int s) {
    for (int j = 0; j < cols_; ++j) std::swap((*this)(r, j), (*this)(s, j));
  }
  friend bool operator==(const RationalMatrix& x, const RationalMatrix& y) {
    return x.rows_ == y.rows_ && x.cols_ == y.cols_ && x.a_ == y.a_;
  }

  /// `m << a, b, c` fills entries in row-major order.
  class Filler {
   public:
    Filler(RationalMatrix& m, const Rational& first) : m_(m) { put(first); }
    Filler& operator,(const Rational& v) {
      put(v);
      return *this;
    }

   private:
    void put(const Rational& v) {
      if (k_ < m_.a_.size()) m_.a_[k_++] = v;
    }
    RationalMatrix& m_;
    std::size_t k_ = 0;
  };
  friend Filler operator<<(RationalMatrix& m, const Rational& first) { return Filler(m, first); }

 private:
  int rows_, cols_;
  std::vector<Rational> a_;
};

/// A 4x4 transform (row-vector convention: [x y z 1]·M).
class Matrix4 : public RationalMatrix {
 public:
  Matrix4() : RationalMatrix(4, 4) {}
};

/// A homogeneous row [x y z w].
class RowVector4 : public RationalMatrix {
 public:
  RowVector4() : RationalMatrix(1, 4) {}
  Rational& operator()(int i) { return RationalMatrix::operator()(0, i); }
  const Rational& operator()(int i) const { return RationalMatrix::operator()(0, i); }
};

/// Roberts' body matrix: 4 rows, one column per face plane.
class BodyMatrixData : public RationalMatrix {
 public:
  BodyMatrixData() : RationalMatrix(4, 0) {}
  BodyMatrixData(int rows, int cols) : RationalMatrix(rows, cols) {}
};

}  // namespace hlr
