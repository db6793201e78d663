// embed.cc - mdlc as a library: compile a model from a file and a model from
// text in memory, then query the plants they become.
//
//   embed examples/urdf/double_pendulum.urdf
//
// mdlc::Compile runs the whole pipeline (frontend: text -> IR; passes:
// resolve and check the IR; backend: IR -> plant and scene graph). The plant
// is plain data (backend/plant.h); poses and the mass matrix at any
// configuration are methods of the Result.
#include <mdlc/mdlc.h>
#include <mdlc/kinematics.h>

#include <cstdio>
#include <iostream>

namespace {

// A model a program might generate: one pendulum, as URDF text.
constexpr const char* kGeneratedUrdf = R"(<?xml version="1.0"?>
<robot name="generated_pendulum">
  <link name="world"/>
  <link name="arm">
    <inertial><origin xyz="0 0 -0.5"/><mass value="2"/>
      <inertia ixx="0.1" iyy="0.1" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="world"/><child link="arm"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="10" velocity="5"/>
  </joint>
</robot>)";

// Prints diagnostics; returns false when the compile failed.
bool Report(const mdlc::Result& result, const char* what) {
  for (const mdlc::Diagnostic& d : result.diagnostics()) std::cerr << result.FormatText(d);
  if (!result.ok()) std::cerr << what << ": compilation failed\n";
  return result.ok();
}

void PrintModel(const mdlc::Result& result, const char* what) {
  const mdlc::backend::Plant& plant = result.plant();
  const Eigen::VectorXd q = mdlc::DefaultPositions(result);
  const std::vector<mdlc::Transform> X_WB = mdlc::BodyPoses(result, q);
  std::printf("%s: bodies %zu, positions %d, velocities %d\n", what, plant.bodies.size() - 1,
              plant.num_positions, plant.num_velocities);
  for (mdlc::BodyId id : plant.body_order) {
    const mdlc::backend::PlantBody& body = plant.body(id);
    if (body.is_world) continue;
    const Eigen::Vector3d& p = X_WB[id.index()].p;
    std::printf("  %-28s mass %8.4g kg  at (%.4f, %.4f, %.4f) m\n", plant.ScopedName(body).c_str(),
                body.mass, p.x(), p.y(), p.z());
  }
  // M(q) is nv x nv; print it only when it is small
  if (plant.num_velocities > 12) return;
  const Eigen::MatrixXd M = mdlc::MassMatrix(result, q);
  std::printf("  mass matrix at the default configuration (%ld x %ld):\n",
              static_cast<long>(M.rows()), static_cast<long>(M.cols()));
  for (Eigen::Index r = 0; r < M.rows(); ++r) {
    std::printf("   ");
    for (Eigen::Index c = 0; c < M.cols(); ++c) std::printf(" %10.5f", M(r, c));
    std::printf("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s MODEL_FILE\n", argv[0]);
    return 2;
  }
  std::printf("mdlc %s\n", MDLC_VERSION_STRING);

  // from a file: the format comes from the extension
  const mdlc::Result from_file = mdlc::Compile(mdlc::Input::File(argv[1]));
  if (!Report(from_file, argv[1])) return 1;
  PrintModel(from_file, argv[1]);

  // from text: the name is what diagnostics print (and where relative mesh
  // paths would be looked for); the format is given, or taken from the name
  const mdlc::Result from_text = mdlc::Compile(
      mdlc::Input::Text(kGeneratedUrdf, "generated.urdf", mdlc::Format::Urdf));
  if (!Report(from_text, "generated.urdf")) return 1;
  PrintModel(from_text, "generated.urdf");
  return 0;
}
