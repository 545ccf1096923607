#include "python/json_objects.h"

#include <cmath>

namespace contactcert::python {

namespace py = pybind11;

py::object json_objects(const queries::json& j) {
  using V = queries::json::value_t;
  switch (j.type()) {
    case V::object: {
      py::dict d;
      for (const auto& [key, value] : j.items()) d[py::str(key)] = json_objects(value);
      return d;
    }
    case V::array: {
      py::list l(j.size());
      std::size_t i = 0;
      for (const auto& value : j) l[i++] = json_objects(value);
      return l;
    }
    case V::string:
      return py::str(j.get_ref<const std::string&>());
    case V::boolean:
      return py::bool_(j.get<bool>());
    case V::number_integer:
      return py::int_(j.get<std::int64_t>());
    case V::number_unsigned:
      return py::int_(j.get<std::uint64_t>());
    case V::number_float: {
      const double x = j.get<double>();
      if (std::isfinite(x)) return py::float_(x);
      return py::none();
    }
    default:  // null, and the binary and discarded values that no result holds
      return py::none();
  }
}

}  // namespace contactcert::python
