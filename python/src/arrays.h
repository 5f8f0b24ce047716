// NumPy arrays for the bindings: copies that own their memory, read-only views of memory that
// a Python object keeps alive, and validated inputs.
#pragma once

#include "errors.h"

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>

#include <algorithm>
#include <cstdint>
#include <string>

namespace fosssim::py {

namespace nb = nanobind;

using Array2 = nb::ndarray<nb::numpy, double, nb::shape<-1, 2>>;
using Array1 = nb::ndarray<nb::numpy, double, nb::shape<-1>>;
using View2 = nb::ndarray<nb::numpy, const double, nb::shape<-1, 2>>;
using View1 = nb::ndarray<nb::numpy, const double, nb::shape<-1>>;
/// What setters accept: anything NumPy can turn into a C-contiguous float64 array on the CPU.
using Input = nb::ndarray<const double, nb::c_contig, nb::device::cpu>;

/// An array with an owner as a Python object (property getters would otherwise apply their
/// reference_internal policy, which an array that already has an owner refuses).
template <class A>
nb::object toPython(A&& array) {
  return nb::cast(std::forward<A>(array), nb::rv_policy::automatic);
}

/// A new (rows x cols, or rows when cols is 0) float64 array holding a copy of `data`.
template <class T = double>
nb::object copyArray(const T* data, size_t rows, size_t cols = 0) {
  const size_t count = rows * (cols ? cols : 1);
  T* copy = new T[count > 0 ? count : 1];
  std::copy(data, data + count, copy);
  nb::capsule owner(copy, [](void* p) noexcept { delete[] static_cast<T*>(p); });
  const size_t shape[2] = {rows, cols};
  return toPython(nb::ndarray<nb::numpy, T>(copy, cols ? 2 : 1, shape, owner));
}

/// The values of an (N, 2) input for N particles; throws SceneError otherwise. A flat (2N,) array
/// is refused too: it may be a mistaken array of N x-values and N y-values, and read as pairs it
/// would be taken silently.
inline const double* pairsOf(const Input& a, long particles, const char* what) {
  const bool ok = a.ndim() == 2 && a.shape(0) == static_cast<size_t>(particles) && a.shape(1) == 2;
  if (!ok) {
    std::string shape;
    for (size_t d = 0; d < a.ndim(); ++d) shape += (d ? ", " : "") + std::to_string(a.shape(d));
    throw SceneError(std::string(what) + ": expected an array of shape (" + std::to_string(particles) +
                     ", 2), got shape (" + shape + ")");
  }
  return a.data();
}

/// The values of an (N,) input.
inline const double* valuesOf(const Input& a, long count, const char* what) {
  if (a.ndim() != 1 || a.shape(0) != static_cast<size_t>(count))
    throw SceneError(std::string(what) + ": expected an array of shape (" + std::to_string(count) + ",)");
  return a.data();
}

}  // namespace fosssim::py
