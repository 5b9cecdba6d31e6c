// Copyright contactlaws authors.
//
// The LD_PRELOAD entry points of libcontactlaws_plugin.so: MuJoCo 2.2.2's own
// functions, defined here so that a program linked against libmujoco calls
// these first; each calls the real one, found with dlsym(RTLD_NEXT, name).
//
//   mj_loadXML, mj_loadModel  record the model's file (for messages);
//                             mj_loadXML: the samples' look (CONTACTLAWS_LOOK)
//   mj_makeData               a ContactData for the data of a tagged model
//   mj_resetData              the settled positions (CONTACTLAWS_SETTLE)
//   mj_deleteData             the data's ContactData removed first
//   mj_deleteModel            the model's tags (and any data left) removed
//   mj_step                   the auto timestep (CONTACTLAWS_ACCURACY);
//                             BeforeStep; mj_step; AfterStep; the tagged
//                             contact points appended to d->contact
//   mj_step1, mj_step2        the same step split in two (BeforeStep before
//                             mj_step1, AfterStep after mj_step2)
//   mj_forward                the tagged contact points appended (what
//                             mujoco-simulate calls while paused)
//
// libmujoco calls its own exported functions through its PLT, so these are
// also reached from inside MuJoCo (mj_step calls mj_forward, the compiler
// makes and steps an mjData of its own). Only the outermost call on a thread
// acts: a nested one goes straight to MuJoCo.

#include <dlfcn.h>

#include <cstdio>
#include <cstdlib>

#include <mujoco/mujoco.h>

#include "plugin/plugin.h"

namespace contactlaws::plugin {
namespace {

// MuJoCo's definition of name, after this library in the lookup order.
template <typename Function>
Function Real(const char* name) {
  void* symbol = dlsym(RTLD_NEXT, name);
  if (!symbol) {
    std::fprintf(stderr, "contactlaws: plugin: %s not found after the plugin (is the program "
                 "linked against libmujoco 2.2.2?)\n", name);
    std::abort();
  }
  return reinterpret_cast<Function>(symbol);
}

#define CONTACTLAWS_REAL(name) \
  static const auto real = Real<decltype(&::name)>(#name)

// Depth of wrapped calls on this thread: only depth 0 acts.
thread_local int wrapped_depth = 0;

class Nesting {
 public:
  Nesting() { ++wrapped_depth; }
  ~Nesting() { --wrapped_depth; }
  Nesting(const Nesting&) = delete;
  Nesting& operator=(const Nesting&) = delete;
  bool outermost() const { return wrapped_depth == 1; }
};

// d's laws when this is the outermost call, else nullptr.
ManagedData* Managed(const Nesting& nesting, const mjData* d) {
  return nesting.outermost() ? Plugin::Get().Find(d) : nullptr;
}

// Before a step of managed (d's): the program's options (m's) as the data's
// own, with CONTACTLAWS_ACCURACY the auto timestep's step.
void Begin(const mjModel* m, mjData* d, ManagedData* managed) {
  // the program's options (its integrator the ledger books by, whatever its
  // user set since)
  mjOption& options = managed->contacts.options();
  options = m->opt;
  if (managed->auto_step) options.timestep = managed->auto_step->Next(d, kPluginMaxStep);
  managed->contacts.BeforeStep();
}

// What MuJoCo steps d with: the data's view of m with the auto timestep, else
// the program's m as given.
const mjModel* Stepped(const mjModel* m, const ManagedData* managed) {
  return managed && managed->auto_step ? managed->contacts.model_view() : m;
}

void Finish(ManagedData* managed) {
  managed->contacts.AfterStep();  // lists the tagged points in d->contact too
  Plugin::Get().ReportDivergence(managed);
}

}  // namespace
}  // namespace contactlaws::plugin

using contactlaws::plugin::Begin;
using contactlaws::plugin::Finish;
using contactlaws::plugin::Managed;
using contactlaws::plugin::ManagedData;
using contactlaws::plugin::Nesting;
using contactlaws::plugin::Plugin;
using contactlaws::plugin::Real;
using contactlaws::plugin::Stepped;

extern "C" {

mjModel* mj_loadXML(const char* filename, const mjVFS* vfs, char* error, int error_sz) {
  CONTACTLAWS_REAL(mj_loadXML);
  Nesting nesting;
  mjModel* m = real(filename, vfs, error, error_sz);
  if (nesting.outermost()) {
    m = contactlaws::plugin::WithLook(m, filename, vfs);
    Plugin::Get().Loaded(m, filename);
  }
  return m;
}

mjModel* mj_loadModel(const char* filename, const mjVFS* vfs) {
  CONTACTLAWS_REAL(mj_loadModel);
  Nesting nesting;
  mjModel* m = real(filename, vfs);
  if (nesting.outermost()) Plugin::Get().Loaded(m, filename);
  return m;
}

mjData* mj_makeData(const mjModel* m) {
  CONTACTLAWS_REAL(mj_makeData);
  Nesting nesting;
  mjData* d = real(m);
  if (nesting.outermost()) Plugin::Get().Made(m, d);
  return d;
}

void mj_resetData(const mjModel* m, mjData* d) {
  CONTACTLAWS_REAL(mj_resetData);
  Nesting nesting;
  real(m, d);
  if (nesting.outermost()) Plugin::Get().ResetDone(m, d);
}

void mj_deleteData(mjData* d) {
  CONTACTLAWS_REAL(mj_deleteData);
  Nesting nesting;
  if (nesting.outermost() && d) Plugin::Get().Deleting(d);
  real(d);
}

void mj_deleteModel(mjModel* m) {
  CONTACTLAWS_REAL(mj_deleteModel);
  Nesting nesting;
  if (nesting.outermost() && m) Plugin::Get().DeletingModel(m);
  real(m);
}

void mj_step(const mjModel* m, mjData* d) {
  CONTACTLAWS_REAL(mj_step);
  Nesting nesting;
  ManagedData* managed = Managed(nesting, d);
  if (managed) Begin(m, d, managed);
  real(Stepped(m, managed), d);
  if (managed) Finish(managed);
}

void mj_step1(const mjModel* m, mjData* d) {
  CONTACTLAWS_REAL(mj_step1);
  Nesting nesting;
  ManagedData* managed = Managed(nesting, d);
  if (managed) Begin(m, d, managed);
  real(Stepped(m, managed), d);
}

void mj_step2(const mjModel* m, mjData* d) {
  CONTACTLAWS_REAL(mj_step2);
  Nesting nesting;
  ManagedData* managed = Managed(nesting, d);
  real(Stepped(m, managed), d);
  if (managed) Finish(managed);
}

void mj_forward(const mjModel* m, mjData* d) {
  CONTACTLAWS_REAL(mj_forward);
  Nesting nesting;
  ManagedData* managed = Managed(nesting, d);
  real(m, d);
  if (managed) AppendVisibleContacts(managed->contacts, d, &managed->overflow);
}

}  // extern "C"
