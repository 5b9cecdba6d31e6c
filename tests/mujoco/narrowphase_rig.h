// Copyright contactlaws authors.
//
// The MuJoCo side of the narrowphase tests: two geoms placed by the oracle
// (narrowphase_oracle.h), a collision function called on them, and what it
// returned measured against the exact answer.

#ifndef CONTACTLAWS_TESTS_MUJOCO_NARROWPHASE_RIG_H_
#define CONTACTLAWS_TESTS_MUJOCO_NARROWPHASE_RIG_H_

#include "mujoco/narrowphase_oracle.h"

namespace narrowphase_test {

// A narrowphase under test: the contacts of geoms g0, g1 (margin 0) in con.
using Collider = int (*)(const mjModel* m, const mjData* d, int g0, int g1, mjContact* con);

// MuJoCo 2.2.2's own.
inline int MujocoCollide(const mjModel* m, const mjData* d, int g0, int g1, mjContact* con) {
  return mjCOLLISIONFUNC[m->geom_type[g0]][m->geom_type[g1]](m, d, con, g0, g1, 0);
}

//---------------------------------- MuJoCo side ---------------------------------------------------

struct ModelDeleter {
  void operator()(mjModel* m) const { mj_deleteModel(m); }
};
struct DataDeleter {
  void operator()(mjData* d) const { mj_deleteData(d); }
};
struct VfsDeleter {
  void operator()(mjVFS* v) const {
    mj_deleteVFS(v);
    delete v;
  }
};
using UniqueModel = std::unique_ptr<mjModel, ModelDeleter>;
using UniqueData = std::unique_ptr<mjData, DataDeleter>;

// Loads an MJCF string through MuJoCo's virtual file system.
inline UniqueModel LoadXml(const std::string& xml, const std::string& name) {
  // mjVFS holds mjMAXVFS names and pointers: too large for the stack
  std::unique_ptr<mjVFS, VfsDeleter> vfs(new mjVFS);
  mj_defaultVFS(vfs.get());
  if (mj_makeEmptyFileVFS(vfs.get(), name.c_str(), static_cast<int>(xml.size())) != 0) {
    ADD_FAILURE() << name << ": could not make a VFS file";
    return nullptr;
  }
  const int index = mj_findFileVFS(vfs.get(), name.c_str());
  std::memcpy(vfs->filedata[index], xml.data(), xml.size());
  char error[1000] = "";
  UniqueModel m(mj_loadXML(name.c_str(), vfs.get(), error, sizeof(error)));
  if (!m) ADD_FAILURE() << name << ": " << error;
  return m;
}

inline std::string GeomXml(int type) {
  const Vec3 s = GeomSize(type);
  char buf[200];
  switch (type) {
    case mjGEOM_PLANE: return R"(<geom type="plane" size="0 0 1"/>)";
    case mjGEOM_HFIELD: return R"(<geom type="hfield" hfield="flat"/>)";
    case mjGEOM_MESH: return R"(<geom type="mesh" mesh="boxmesh"/>)";
    default:
      std::snprintf(buf, sizeof(buf), R"(<geom type="%s" size="%.17g %.17g %.17g"/>)",
                    TypeName(type), s[0], s[1], s[2]);
      return buf;
  }
}

// Two geoms: geom 0 (bottom) on the world or a free body, geom 1 (top) on a
// free body. The mesh is the box of GeomSize(mjGEOM_MESH), given by vertices.
inline std::string PairXml(int bottom, int top) {
  const Vec3 b = GeomSize(mjGEOM_MESH);
  const Vec3 h = GeomSize(mjGEOM_HFIELD);
  char assets[1200];
  std::snprintf(assets, sizeof(assets),
                R"(<asset>
    <hfield name="flat" nrow="11" ncol="11" size="%g %g 0.1 %g"/>
    <mesh name="boxmesh" vertex="-%g -%g -%g  %g -%g -%g  -%g %g -%g  %g %g -%g
                                  -%g -%g %g  %g -%g %g  -%g %g %g  %g %g %g"/>
  </asset>)",
                h[0], h[1], h[2], b[0], b[1], b[2], b[0], b[1], b[2], b[0], b[1], b[2], b[0],
                b[1], b[2], b[0], b[1], b[2], b[0], b[1], b[2], b[0], b[1], b[2], b[0], b[1],
                b[2]);
  std::string world;
  if (IsGround(bottom)) {
    world = "    " + GeomXml(bottom) + "\n";
  } else {
    world = "    <body><freejoint/>" + GeomXml(bottom) + "</body>\n";
  }
  world += "    <body><freejoint/>" + GeomXml(top) + "</body>\n";
  return std::string("<mujoco>\n  ") + assets + "\n  <worldbody>\n" + world +
         "  </worldbody>\n</mujoco>\n";
}

//---------------------------------- one measurement -------------------------------------------------

// What MuJoCo returned for one configuration, against the exact answer.
struct Measurement {
  std::string pair, config;
  double fraction = 0;        // overlap / kSize
  double exact = 0;           // exact depth (m)
  double depth = 0;           // MuJoCo's deepest contact, -min(dist) (m); 0 if none
  int ncon = 0;
  double depth_error = 0;     // (depth - exact) / exact
  double witness = 0;         // worst distance of a contact's witness point from its surface / exact
  double normal_degrees = 0;  // worst angle between frame[0..2] and +z
};

// Places the pair, runs MuJoCo's collision function, compares.
class PairRig {
 public:
  PairRig(int bottom, int top, Collider collide = MujocoCollide)
      : bottom_(bottom), top_(top), name_(std::string(TypeName(bottom)) + "-" + TypeName(top)),
        collide_(collide) {
    model_ = LoadXml(PairXml(bottom, top), name_ + ".xml");
    if (model_) data_.reset(mj_makeData(model_.get()));
  }
  bool ok() const { return data_ != nullptr; }
  const std::string& name() const { return name_; }
  mjModel* model() { return model_.get(); }
  void PrintContacts(bool on) { print_contacts_ = on; }
  const std::vector<mjContact>& LastContacts() const { return last_; }

  Measurement Measure(const Config& config, double fraction) {
    Measurement r;
    r.pair = name_;
    r.config = config.name;
    r.fraction = fraction;
    r.exact = fraction * kSize;

    // bottom geom: at the origin (a ground geom: the contact moved off the hfield grid lines)
    Shape lower{bottom_, GeomSize(bottom_)};
    const Quat qb = Then(Rest(bottom_), config.bottom);
    Vec3 high{0.037, 0.023, 0};
    if (!IsGround(bottom_)) {
      lower.rot = QuatToMat(qb);
      high = Support(lower, {0, 0, 1});
    }

    // top geom: its lowest point `exact` below the bottom geom's highest point
    Shape upper{top_, GeomSize(top_)};
    const Quat qt = Then(Rest(top_), config.top);
    upper.rot = QuatToMat(qt);
    const Vec3 low = Support(upper, {0, 0, -1});
    upper.pos = Sub(Add(high, {config.offset[0], config.offset[1], -r.exact}), low);

    // MuJoCo: the same poses through the free joints
    mjtNum* q = data_->qpos;
    if (!IsGround(bottom_)) {
      for (int i = 0; i < 3; ++i) q[i] = lower.pos[i];
      for (int i = 0; i < 4; ++i) q[3 + i] = qb[i];
      q += 7;
    }
    for (int i = 0; i < 3; ++i) q[i] = upper.pos[i];
    for (int i = 0; i < 4; ++i) q[3 + i] = qt[i];
    mj_kinematics(model_.get(), data_.get());
    mjContact con[mjMAXCONPAIR];
    std::memset(con, 0, sizeof(con));
    r.ncon = collide_(model_.get(), data_.get(), 0, 1, con);

    // each contact's witness points pos -+ normal*dist/2 must lie on the surfaces
    for (int i = 0; i < r.ncon; ++i) {
      const mjContact& c = con[i];
      const Vec3 n = Scale({c.frame[0], c.frame[1], c.frame[2]},
                           1 / Norm({c.frame[0], c.frame[1], c.frame[2]}));
      const Vec3 pos = {c.pos[0], c.pos[1], c.pos[2]};
      r.depth = std::max(r.depth, -c.dist);
      r.normal_degrees = std::max(r.normal_degrees, std::acos(std::clamp(n[2], -1.0, 1.0)) * 180 / kPi);
      const double miss1 = WitnessMiss(lower, Sub(pos, Scale(n, 0.5 * c.dist)), n, false);
      const double miss2 = WitnessMiss(upper, Add(pos, Scale(n, 0.5 * c.dist)), n, true);
      r.witness = std::max({r.witness, std::fabs(miss1) / r.exact, std::fabs(miss2) / r.exact});
      if (print_contacts_) {
        std::printf("  %-19s %-8s %7.0e #%d pos %+.6f %+.6f %+.9f dist %+.4e n %+.3f %+.3f %+.3f"
                    " miss %+.2e %+.2e\n", r.pair.c_str(), r.config.c_str(), fraction, i,
                    pos[0], pos[1], pos[2], c.dist, n[0], n[1], n[2], miss1, miss2);
      }
    }
    last_.assign(con, con + r.ncon);
    r.depth_error = (r.depth - r.exact) / r.exact;
    return r;
  }

 private:
  int bottom_, top_;
  std::string name_;
  Collider collide_;
  UniqueModel model_;
  UniqueData data_;
  bool print_contacts_ = false;
  std::vector<mjContact> last_;
};

// Every pair MuJoCo 2.2.2 collides: upper triangle of mjCOLLISIONFUNC.
inline std::vector<std::pair<int, int>> CollidedPairs() {
  std::vector<std::pair<int, int>> pairs;
  for (int i = 0; i < mjNGEOMTYPES; ++i) {
    for (int j = i; j < mjNGEOMTYPES; ++j) {
      if (mjCOLLISIONFUNC[i][j]) pairs.emplace_back(i, j);
    }
  }
  return pairs;
}

inline std::vector<Measurement> MeasureAll(int bottom, int top, bool print_contacts = false,
                                           Collider collide = MujocoCollide) {
  PairRig rig(bottom, top, collide);
  rig.PrintContacts(print_contacts);
  std::vector<Measurement> rows;
  if (!rig.ok()) return rows;
  for (const Config& c : ConfigsFor(bottom, top)) {
    for (double f : kOverlapFractions) rows.push_back(rig.Measure(c, f));
  }
  return rows;
}

inline void PrintRow(const Measurement& r) {
  std::printf("%-19s %-8s %7.0e %10.3e %10.3e %+10.2e %3d %9.2e %7.2f\n", r.pair.c_str(),
              r.config.c_str(), r.fraction, r.exact, r.depth, r.depth_error, r.ncon, r.witness,
              r.normal_degrees);
}

inline void PrintHeader() {
  std::printf("%-19s %-8s %7s %10s %10s %10s %3s %9s %7s\n", "pair", "config", "ovl/size",
              "exact(m)", "mujoco(m)", "rel.err", "n", "witness", "n.deg");
}

//---------------------------------- fixture -------------------------------------------------------

// Fails the test on any MuJoCo warning.
class Narrowphase : public ::testing::Test {
 protected:
  void SetUp() override {
    previous_ = mju_user_warning;
    mju_user_warning = [](const char* msg) { ADD_FAILURE() << "MuJoCo warning: " << msg; };
  }
  void TearDown() override { mju_user_warning = previous_; }

 private:
  void (*previous_)(const char*) = nullptr;
};

using NarrowphaseSurvey = Narrowphase;


// All the measurements of one pair type.
inline std::vector<Measurement> Rows(int bottom, int top, Collider collide = MujocoCollide) {
  return MeasureAll(bottom, top, false, collide);
}

// The measurement of one configuration.
inline Measurement Row(int bottom, int top, const std::string& config, double fraction,
                       Collider collide = MujocoCollide) {
  for (const Measurement& r : MeasureAll(bottom, top, false, collide)) {
    if (r.config == config && r.fraction == fraction) return r;
  }
  ADD_FAILURE() << TypeName(bottom) << "-" << TypeName(top) << ": no " << config;
  return {};
}

// The contacts of one configuration, for the tests that look at positions.
inline std::vector<mjContact> Contacts(int bottom, int top, const Config& config,
                                       double fraction, Collider collide = MujocoCollide) {
  PairRig rig(bottom, top, collide);
  rig.Measure(config, fraction);
  return rig.LastContacts();
}

inline const Config& FindConfig(int bottom, int top, const std::string& name) {
  static std::vector<Config> all;
  all = ConfigsFor(bottom, top);
  for (const Config& c : all) {
    if (c.name == name) return c;
  }
  ADD_FAILURE() << "no configuration " << name;
  return all.front();
}

}  // namespace narrowphase_test

#endif  // CONTACTLAWS_TESTS_MUJOCO_NARROWPHASE_RIG_H_
