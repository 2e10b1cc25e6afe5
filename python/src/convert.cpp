#include "convert.h"

#include <gmcc/input/colour_csv.h>

#include <cmath>
#include <cstdint>
#include <cstring>

namespace gmcc::python {
namespace {

const char* const channel_names[] = {"r", "g", "b"};

// The largest int (numerator or denominator) accepted: 2^65536, about 19,700 digits.
constexpr std::size_t max_integer_bits = 65536;

py::object fraction_type() {
  static py::object* type = new py::object(py::module_::import("fractions").attr("Fraction"));
  return *type;
}
py::object numbers_attr(const char* name) {
  return py::module_::import("numbers").attr(name);
}

// The exact integer of a Python int, with the digit limit the command line puts on a number.
mpz_class int_from(py::handle x, const std::string& where) {
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(x.ptr(), &overflow);
  if (!overflow) {
    if (v == -1 && PyErr_Occurred()) throw py::error_already_set();
    mpz_class z;
    if (v >= 0) mpz_set_ui(z.get_mpz_t(), static_cast<unsigned long>(v));
    else z = mpz_class(std::to_string(v));
    return z;
  }
  // Exact values gmcc itself returns (a 2-D mean of hundreds of digits) must come back in; the
  // bound only keeps a run finite. Text has the command line's tighter limit (parse_rational).
  const std::size_t bits = _PyLong_NumBits(x.ptr());
  if (bits > max_integer_bits)
    throw py::value_error(where + ": an integer of " + std::to_string(bits) + " bits: at most " +
                          std::to_string(max_integer_bits) + " bits are accepted");
  const std::string hex = py::str(py::reinterpret_borrow<py::object>(py::module_::import("builtins").attr("hex"))(x));
  // hex() gives [-]0x…
  const bool negative = hex[0] == '-';
  mpz_class z(hex.substr(negative ? 3 : 2), 16);
  return negative ? mpz_class(-z) : z;
}

Rational from_double(double v, const std::string& where) {
  if (std::isnan(v))
    throw py::value_error(where + ": NaN is not allowed: a colour channel must be a finite number");
  if (std::isinf(v))
    throw py::value_error(where + ": infinity is not allowed: a colour channel must be finite");
  return rational_from_double(v);
}

std::string type_name(py::handle x) { return py::str(py::type::handle_of(x).attr("__name__")); }

[[noreturn]] void not_a_number(py::handle x, const std::string& where) {
  throw py::type_error(where + ": expected a number (int, float, fractions.Fraction or str), got " +
                       type_name(x));
}

// The channel of one colour in a message: `canonical: row 3: channel g`.
std::string channel_where(const std::string& argument, std::size_t row, int k) {
  return argument + ": row " + std::to_string(row) + ": channel " + channel_names[k];
}

void check_channel(const Rational& v, const std::string& where, py::handle shown) {
  if (sgn(v) < 0) {
    std::string text = shown ? std::string(py::str(shown)) : to_string(v);
    if (text.size() > 40) text = text.substr(0, 40) + "...";
    // where = "ARG: row N: channel c": the command line's "channel c is negative (...)".
    throw py::value_error(where + " is negative (" + text + "): a linear sensor response must be >= 0");
  }
}

template <class T>
T load(const char* p) {
  T v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// Colours from a numpy array of a real dtype, any strides; native byte order.
// The command line's cap on a colour list (colour_csv.h's max_colours, 10^6): exact colours take
// hundreds of bytes each, so 10^7 would take gigabytes before any work (issue 30).
static void check_colour_count(std::size_t n, const std::string& argument) {
  if (n > max_colours)
    throw py::value_error(argument + ": " + std::to_string(n) + " colours, more than the " +
                          std::to_string(max_colours) +
                          " a colour list may hold (as in a colour file); an image's colours go through "
                          "gmcc.image_colours, which keeps only its hull");
}

std::vector<Colour> colours_from_array(py::array a, const std::string& argument) {
  if (a.ndim() != 2 || a.shape(1) != 3) {
    std::string shape = "(";
    for (py::ssize_t d = 0; d < a.ndim(); ++d) shape += (d ? ", " : "") + std::to_string(a.shape(d));
    shape += a.ndim() == 1 ? ",)" : ")";
    throw py::value_error(argument + ": expected an N×3 array of colours r,g,b, got shape " + shape);
  }
  const char kind = a.dtype().kind();
  if (kind == 'O') return colours_from(py::list(a.attr("tolist")()), argument);
  if (kind == 'b')
    throw py::type_error(argument + ": a bool array is not colours (expected a real dtype)");
  if (kind != 'f' && kind != 'i' && kind != 'u')
    throw py::type_error(argument + ": dtype " + std::string(py::str(a.dtype())) +
                         " is not a real number type (expected float or int)");
  if (kind == 'f' && a.itemsize() > 8)
    throw py::type_error(argument + ": dtype " + std::string(py::str(a.dtype())) +
                         " has no exact double value; convert it to float64 or give Fractions");
  const char order = a.dtype().attr("byteorder").cast<std::string>()[0];
  const bool native = order == '=' || order == '|' ||
                      (order == '<') == (py::module_::import("sys").attr("byteorder").cast<std::string>() == "little");
  if (!native || (kind == 'f' && a.itemsize() == 2))  // float16 and swapped data: as float64 / native
    a = a.attr("astype")(kind == 'f' ? py::dtype("float64") : a.dtype().attr("newbyteorder")("="));
  const std::size_t n = static_cast<std::size_t>(a.shape(0));
  if (n == 0) throw py::value_error(argument + ": no colours (expected an N×3 array, N >= 1)");
  check_colour_count(n, argument);
  const char* base = static_cast<const char*>(a.data());
  const py::ssize_t s0 = a.strides(0), s1 = a.strides(1), size = a.itemsize();
  std::vector<Colour> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    Rational* ch[3] = {&out[i].r, &out[i].g, &out[i].b};
    for (int k = 0; k < 3; ++k) {
      const char* p = base + static_cast<py::ssize_t>(i) * s0 + k * s1;
      Rational& v = *ch[k];
      if (kind == 'f') {
        const double d = size == 4 ? double(load<float>(p)) : load<double>(p);
        if (!std::isfinite(d)) v = from_double(d, channel_where(argument, i, k));
        else if (d < 0) throw py::value_error(channel_where(argument, i, k) + " is negative (" +
                                              std::string(py::str(py::float_(d))) +
                                              "): a linear sensor response must be >= 0");
        else v = rational_from_double(d);
      } else if (kind == 'i') {
        const long long x = size == 1 ? load<std::int8_t>(p) : size == 2 ? load<std::int16_t>(p)
                          : size == 4 ? load<std::int32_t>(p) : load<std::int64_t>(p);
        if (x < 0)
          throw py::value_error(channel_where(argument, i, k) + " is negative (" + std::to_string(x) +
                                "): a linear sensor response must be >= 0");
        mpz_set_ui(v.get_num_mpz_t(), static_cast<unsigned long>(x));
      } else {
        const unsigned long long x = size == 1 ? load<std::uint8_t>(p) : size == 2 ? load<std::uint16_t>(p)
                                   : size == 4 ? load<std::uint32_t>(p) : load<std::uint64_t>(p);
        mpz_set_ui(v.get_num_mpz_t(), static_cast<unsigned long>(x));
      }
    }
  }
  return out;
}

bool is_text(py::handle x) { return py::isinstance<py::str>(x) || py::isinstance<py::bytes>(x); }

}  // namespace

py::object to_int(const mpz_class& z) {
  if (z.fits_slong_p()) return py::reinterpret_steal<py::object>(PyLong_FromLong(z.get_si()));
  const std::string hex = z.get_str(16);
  return py::reinterpret_steal<py::object>(PyLong_FromString(hex.c_str(), nullptr, 16));
}

py::object to_fraction(const Rational& x) {
  return fraction_type()(to_int(x.get_num()), to_int(x.get_den()));
}

py::tuple to_fraction_pair(const Point2& p) { return py::make_tuple(to_fraction(p.x), to_fraction(p.y)); }

Rational number_from(py::handle x, const std::string& where) {
  if (PyBool_Check(x.ptr()) || py::isinstance(x, py::module_::import("numpy").attr("bool_")))
    throw py::type_error(where + ": a bool is not a number");
  if (PyFloat_Check(x.ptr())) return from_double(PyFloat_AsDouble(x.ptr()), where);
  if (PyLong_Check(x.ptr())) return Rational(int_from(x, where));
  if (py::isinstance<py::str>(x)) {
    try {
      return parse_rational(x.cast<std::string>());
    } catch (const std::invalid_argument& e) {
      throw py::value_error(where + ": " + e.what());
    }
  }
  if (py::isinstance(x, numbers_attr("Rational"))) {  // Fraction, numpy integers
    Rational q(int_from(py::int_(x.attr("numerator")), where),
               int_from(py::int_(x.attr("denominator")), where));
    if (sgn(q.get_den()) == 0) throw py::value_error(where + ": divides by zero");
    q.canonicalize();
    return q;
  }
  if (py::isinstance(x, numbers_attr("Real"))) {  // numpy float32/float16, other reals
    const py::object f = py::float_(py::reinterpret_borrow<py::object>(x));
    return from_double(PyFloat_AsDouble(f.ptr()), where);
  }
  if (py::isinstance(x, py::module_::import("decimal").attr("Decimal"))) {
    try {
      return parse_rational(std::string(py::str(x)));
    } catch (const std::invalid_argument& e) {
      throw py::value_error(where + ": " + e.what());
    }
  }
  not_a_number(x, where);
}

std::vector<Colour> colours_from(py::handle x, const std::string& argument) {
  if (py::isinstance<py::array>(x)) return colours_from_array(py::reinterpret_borrow<py::array>(x), argument);
  if (x.is_none()) throw py::type_error(argument + ": expected colours (an N×3 array or rows r,g,b), got None");
  if (is_text(x) || !py::isinstance<py::sequence>(x)) {
    // Other array-likes (a pandas DataFrame, a memoryview): through numpy.
    if (!is_text(x) && py::hasattr(x, "__array__"))
      return colours_from_array(py::module_::import("numpy").attr("asarray")(x), argument);
    throw py::type_error(argument + ": expected colours (an N×3 array or a sequence of rows r,g,b), got " +
                         type_name(x));
  }
  const py::sequence rows = py::reinterpret_borrow<py::sequence>(x);
  if (rows.size() == 0) throw py::value_error(argument + ": no colours (expected rows r,g,b)");
  check_colour_count(rows.size(), argument);
  std::vector<Colour> out;
  out.reserve(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const py::object row = rows[i];
    if (is_text(row) || !py::isinstance<py::sequence>(row))
      throw py::type_error(argument + ": row " + std::to_string(i) + ": expected r,g,b (3 numbers), got " +
                           type_name(row));
    const py::sequence r = py::reinterpret_borrow<py::sequence>(row);
    if (r.size() != 3)
      throw py::value_error(argument + ": row " + std::to_string(i) + ": expected 3 values r,g,b, found " +
                            std::to_string(r.size()));
    Colour c;
    Rational* ch[3] = {&c.r, &c.g, &c.b};
    for (int k = 0; k < 3; ++k) {
      const std::string where = channel_where(argument, i, k);
      const py::object v = r[k];
      *ch[k] = number_from(v, where);
      check_channel(*ch[k], where, v);
    }
    out.push_back(std::move(c));
  }
  return out;
}

Colour light_from(py::handle x, const std::string& argument) {
  std::vector<Colour> one;
  if (py::isinstance<py::str>(x)) {  // "r,g,b", as the command line's light options
    py::list fields = x.attr("split")(",");
    if (fields.size() != 3)
      throw py::value_error(argument + ": expected one light r,g,b (3 numbers), found " +
                            std::to_string(fields.size()) + " in " + quoted_text(x.cast<std::string>()));
    py::list stripped;
    for (py::handle f : fields) stripped.append(f.attr("strip")());
    one = colours_from(py::make_tuple(stripped), argument);
  } else if (py::isinstance<py::array>(x) && py::reinterpret_borrow<py::array>(x).ndim() == 1) {
    if (py::len(x) != 3)
      throw py::value_error(argument + ": expected one light r,g,b (3 numbers), found " + std::to_string(py::len(x)));
    one = colours_from(py::module_::import("numpy").attr("reshape")(x, py::make_tuple(1, -1)), argument);
  } else if (!is_text(x) && py::isinstance<py::sequence>(x) && py::len(x) > 0 &&
             [](py::handle first) { return is_text(first) || !py::isinstance<py::sequence>(first); }(
                 py::reinterpret_borrow<py::sequence>(x)[0])) {
    if (py::len(x) != 3)
      throw py::value_error(argument + ": expected one light r,g,b (3 numbers), found " + std::to_string(py::len(x)));
    one = colours_from(py::make_tuple(x), argument);
  } else {
    one = colours_from(x, argument);
  }
  if (one.size() != 1) throw py::value_error(argument + ": expected one light r,g,b");
  const Colour& l = one[0];
  for (const Rational* v : {&l.r, &l.g, &l.b})
    if (sgn(*v) <= 0) throw py::value_error(argument + ": every channel must be > 0");
  return l;
}

Point2 map_from(py::handle x, const std::string& argument) {
  if (is_text(x) || !(py::isinstance<py::sequence>(x) || py::isinstance<py::array>(x)))
    throw py::type_error(argument + ": expected a map (m1, m2), got " + type_name(x));
  const py::list items(py::reinterpret_borrow<py::object>(x));
  if (items.size() != 2)
    throw py::value_error(argument + ": expected a map of 2 numbers (m1, m2), found " + std::to_string(items.size()));
  return {number_from(items[0], argument + "[0]"), number_from(items[1], argument + "[1]")};
}

py::array_t<double> float_array(const std::vector<double>& values, std::size_t rows, std::size_t cols) {
  py::array_t<double> a({static_cast<py::ssize_t>(rows), static_cast<py::ssize_t>(cols)});
  if (!values.empty()) std::memcpy(a.mutable_data(), values.data(), values.size() * sizeof(double));
  return a;
}

}  // namespace gmcc::python
