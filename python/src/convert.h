#pragma once
/// \file convert.h
/// The binding's one boundary between Python objects and gmcc's exact values (docs/python.md
/// "Input"): numbers, colours, lights and maps in; rationals as fractions.Fraction out. Every
/// conversion is exact: a Python float (or a numpy floating value) becomes the rational of its
/// value (rational_from_double), an int or a Fraction its own value, a str is read by
/// parse_rational as the command line reads a file (`0.1` is 1/10). Bad input raises ValueError or
/// TypeError naming the argument and the row (0-based), in the command line's words.

#include <gmcc/geometry/colour.h>
#include <gmcc/geometry/point.h>
#include <gmcc/geometry/rational.h>

#include <gmcc/selection/option_error.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace gmcc::python {

namespace py = pybind11;

/// `x` as a fractions.Fraction (exact).
py::object to_fraction(const Rational& x);
/// (Fraction, Fraction).
py::tuple to_fraction_pair(const Point2& p);
/// A Python int of exactly `z`.
py::object to_int(const mpz_class& z);

/// One number, exactly. \param where names it in messages (`canonical: row 3: channel g`).
/// \throws py::type_error (bool, or not a number, Fraction or str), py::value_error (NaN,
///         infinity, malformed text, beyond the digit or exponent limits).
Rational number_from(py::handle x, const std::string& where);

/// N×3 colours from a numpy array (any real dtype, any strides and byte order) or a sequence of
/// rows of 3 numbers (int, float, Fraction, str, numpy scalars). Channels must be finite and >= 0.
/// \param argument the argument's name in messages. \throws py::value_error, py::type_error.
std::vector<Colour> colours_from(py::handle x, const std::string& argument);

/// One light r,g,b with every channel > 0 (a truth, an illuminant, the canonical light).
Colour light_from(py::handle x, const std::string& argument);

/// A perspective map (m1, m2): two numbers.
Point2 map_from(py::handle x, const std::string& argument);

/// A float numpy array of shape (rows, cols) from row-major doubles.
/// An int argument within [lo, hi] (not a bool), as a T. \throws TypeError, ValueError naming it.
template <class T>
T integer_in(py::handle x, const char* name, unsigned long long lo, unsigned long long hi) {
  if (PyBool_Check(x.ptr()) || !py::isinstance(x, py::module_::import("numbers").attr("Integral")))
    throw py::type_error(std::string(name) + ": expected an int, got " +
                         std::string(py::str(py::type::handle_of(x).attr("__name__"))));
  const py::int_ i(py::reinterpret_borrow<py::object>(x));
  if (i < py::int_(lo) || i > py::int_(hi))
    throw py::value_error(std::string(name) + ": must be from " + std::to_string(lo) + " to " + std::to_string(hi));
  return i.cast<T>();
}

/// The same within a library range (e.g. mean_3d.h's).
template <class T>
T integer_in(py::handle x, const char* name, IntegerRange range) {
  return integer_in<T>(x, name, range.lo, range.hi);
}

py::array_t<double> float_array(const std::vector<double>& values, std::size_t rows, std::size_t cols);

}  // namespace gmcc::python
