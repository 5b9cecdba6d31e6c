// Copyright contactlaws authors.
//
// Keyword arguments into the application's option grammar (app/options.h):
// a number goes in as a number, text as text; messages name the keywords.

#include "bindings.h"

#include <utility>
#include <vector>

namespace contactlaws::python {

namespace py = pybind11;

const app::OptionReader& Keywords() {
  static const app::OptionReader keywords(app::kKeywordSpelling);
  return keywords;
}

namespace {

// An int or a float; a bool is an int to Python, not a number here (its
// text, "True", is refused).
bool IsNumber(const py::handle value) {
  return !py::isinstance<py::bool_>(value) &&
         (py::isinstance<py::float_>(value) || py::isinstance<py::int_>(value));
}

}  // namespace

std::optional<app::Value> ValueOf(const py::dict& kwargs, const char* key) {
  if (!kwargs.contains(key) || kwargs[key].is_none()) return std::nullopt;
  const py::handle value = kwargs[key];
  if (IsNumber(value)) return app::Value(value.cast<double>());
  if (py::isinstance<py::list>(value) || py::isinstance<py::tuple>(value)) {
    std::vector<double> numbers;
    for (const py::handle item : value) {
      if (!IsNumber(item)) return app::Value(py::str(value).cast<std::string>());
      numbers.push_back(item.cast<double>());
    }
    return app::Value(std::move(numbers));
  }
  return app::Value(py::str(value).cast<std::string>());
}

bool Switch(const py::dict& kwargs, const char* key) {
  if (!kwargs.contains(key) || kwargs[key].is_none()) return false;
  if (!py::isinstance<py::bool_>(kwargs[key])) {
    throw py::type_error(std::string(key) + " must be True or False");
  }
  return kwargs[key].cast<bool>();
}

app::CommonInput CommonInputOf(const py::dict& kwargs) {
  app::CommonInput input;
  if (auto v = ValueOf(kwargs, "duration")) input.duration = *v;
  if (auto v = ValueOf(kwargs, "sample_rate")) input.sample_rate = *v;
  input.timestep = ValueOf(kwargs, "timestep");
  input.max_timestep = ValueOf(kwargs, "max_timestep");
  input.accuracy = ValueOf(kwargs, "accuracy");
  input.integrator = OptionalText(kwargs, "integrator");
  input.columns = OptionalText(kwargs, "columns");
  input.dissipation = ValueOf(kwargs, "dissipation");
  input.friction = OptionalText(kwargs, "friction");
  input.mu = ValueOf(kwargs, "mu");
  input.settle = Switch(kwargs, "settle");
  input.contact_steps = ValueOf(kwargs, "contact_steps");
  return input;
}

}  // namespace contactlaws::python
