// Copyright contactlaws authors.
//
// The extension module contactlaws._contactlaws; the package contactlaws
// (python/contactlaws/__init__.py) gives it keywords and DataFrames.

#include "bindings.h"

PYBIND11_MODULE(_contactlaws, m) {
  m.doc() = "contactlaws: continuous contact force laws in MuJoCo 2.2 (C++ core)";
  contactlaws::python::BindKeywordSpelling(m);
  contactlaws::python::BindSimulation(m);
  contactlaws::python::BindCommands(m);
  contactlaws::python::BindJobs(m);
}
