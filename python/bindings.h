// Copyright contactlaws authors.
//
// What the pieces of the extension module share.

#ifndef CONTACTLAWS_PYTHON_BINDINGS_H_
#define CONTACTLAWS_PYTHON_BINDINGS_H_

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "app/options.h"
#include "app/table.h"
#include "contactlaws/contactlaws.h"

namespace contactlaws::python {

// A Simulation's data, to write its state and to run mj_forward.
inline mjData* MutableData(Simulation* sim) { return sim->data(); }

// A keyword argument taken as text (a name, a list, a path): absent or None
// -> nullopt, a str as is, anything else as Python's str() of it.
inline std::optional<std::string> OptionalText(const pybind11::dict& kwargs, const char* key) {
  if (!kwargs.contains(key) || kwargs[key].is_none()) return std::nullopt;
  return pybind11::str(kwargs[key]).cast<std::string>();
}

// The options' grammar naming the keyword arguments (python/options.cc).
const app::OptionReader& Keywords();

// A keyword argument as the grammar takes it: absent or None -> nullopt; an
// int or float (not a bool) as a number; a list or tuple of them as numbers
// (the option must take a list); a str as text; anything else as Python's
// str() of it.
std::optional<app::Value> ValueOf(const pybind11::dict& kwargs, const char* key);

// A switch keyword: True or False (absent or None: false); else TypeError.
bool Switch(const pybind11::dict& kwargs, const char* key);

// The keywords of the options run, compare, restitution and check share
// (duration, sample_rate, timestep, ..., settle).
app::CommonInput CommonInputOf(const pybind11::dict& kwargs);

// A scene with the overrides the keywords give (law, restitution, friction,
// mu, timestep).
std::unique_ptr<Simulation> MakeSimulation(const std::string& scene, const pybind11::dict& kwargs);

// values as a 1-D numpy array (a copy).
template <typename T>
pybind11::array_t<T> Array(const std::vector<T>& values) {
  return pybind11::array_t<T>(static_cast<pybind11::ssize_t>(values.size()), values.data());
}

// A result table as {name: column}: a float64 array (NaN: not known), an
// int64 array (a count) or a list of str, in the table's order.
pybind11::dict TableDict(const app::Table& table);

// A command line's message with the keyword arguments' names for its
// flags (python/keywords.cc).
std::string KeywordSpelling(const std::string& message);

// contactlaws.Error and the spelling of every message (KeywordSpelling).
void BindKeywordSpelling(pybind11::module_& m);
void BindSimulation(pybind11::module_& m);
void BindCommands(pybind11::module_& m);
void BindJobs(pybind11::module_& m);

}  // namespace contactlaws::python

#endif  // CONTACTLAWS_PYTHON_BINDINGS_H_
