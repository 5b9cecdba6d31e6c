// Copyright contactlaws authors.
//
// Owning handles for mjModel and mjData, and MJCF loading with messages that
// name the file.

#ifndef CONTACTLAWS_MODEL_IO_H_
#define CONTACTLAWS_MODEL_IO_H_

#include <memory>
#include <string>
#include <string_view>

#include <mujoco/mujoco.h>

namespace contactlaws {

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
using UniqueModel = std::unique_ptr<mjModel, ModelDeleter>;
using UniqueData = std::unique_ptr<mjData, DataDeleter>;

// Loads an MJCF file. Throws Error "PATH: <MuJoCo's message>".
UniqueModel LoadModelFile(const std::string& path);

// Loads MJCF text from memory (through MuJoCo's VFS); name stands for the
// file in messages. Throws Error.
UniqueModel LoadModelString(std::string_view xml, const std::string& name = "inline.xml");

// The name of a MuJoCo object, or "<kind><id>" (geom3, body2) when unnamed:
// how every message and CSV column names geoms and bodies.
std::string ObjectName(const mjModel* m, mjtObj type, int id);

// The mjVERSION_HEADER of the MuJoCo library this process runs (222 = 2.2.2).
int MujocoVersion();

// This library's version ("0.1.0").
std::string_view LibraryVersion();

}  // namespace contactlaws

#endif  // CONTACTLAWS_MODEL_IO_H_
