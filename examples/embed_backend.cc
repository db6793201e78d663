// embed_backend.cc - mdlc as a library: compile a model file, then query the
// multibody plant it becomes.
//
//   mdlc_embed_example examples/urdf/double_pendulum.urdf
//
// mdlc::Compilation (backend/compiler.h) runs the whole pipeline: frontend
// (file -> IR), passes (resolve and check the IR), backend (IR -> plant). The
// plant it produces is plain data (backend/plant.h); kinematics and the mass
// matrix are free functions over it (backend/backend.h includes them all).
#include <fmt/format.h>

#include <Eigen/Core>
#include <vector>

#include "backend/compiler.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    fmt::print(stderr, "usage: {} MODEL_FILE\n", argv[0]);
    return 2;
  }

  // compile; the Compilation owns the source buffers, the IR and the plant,
  // so it must outlive everything that refers into it
  mdlc::Compilation compilation;
  compilation.options.files = {argv[1]};
  const bool ok = compilation.Run();

  // diagnostics are kept in the engine (DiagnosticEngine::SetConsumer would
  // stream them instead); print warnings too, not only errors
  for (const mdlc::Diagnostic& diag : compilation.diags.diagnostics()) {
    fmt::print(stderr, "{}", mdlc::FormatDiagnosticText(diag, compilation.sources));
  }
  if (!ok) {
    fmt::print(stderr, "{}: compilation failed\n", argv[1]);
    return 1;
  }
  const mdlc::backend::Plant& plant = compilation.model->plant;

  // every body's pose in the world at the default configuration (each joint at
  // its default position), parents before children
  const Eigen::VectorXd q = mdlc::backend::DefaultPositions(plant);
  const std::vector<mdlc::Transform> X_WB = mdlc::backend::BodyPosesInWorld(plant, q);
  fmt::print("{} bodies, {} positions, {} velocities\n", plant.bodies.size() - 1,
             plant.num_positions, plant.num_velocities);
  fmt::print("{:<28} {:>9}  {:<26} {}\n", "body", "mass (kg)", "position in world (m)",
             "roll pitch yaw (rad)");
  for (mdlc::BodyId id : plant.body_order) {
    const mdlc::backend::PlantBody& body = plant.body(id);
    if (body.is_world) continue;
    const mdlc::Transform& X = X_WB[id.index()];
    const Eigen::Vector3d rpy = mdlc::RpyFromRotation(X.R).array() + 0.0;  // -0 prints as 0
    fmt::print("{:<28} {:>9.4g}  {:>8.4f} {:>8.4f} {:>8.4f}  {:>7.4f} {:>7.4f} {:>7.4f}\n",
               body.scoped_name, body.mass, X.p.x(), X.p.y(), X.p.z(), rpy.x(), rpy.y(),
               rpy.z());
  }

  // the mass matrix M(q), one row and column per velocity, in the order of the
  // joints in plant.joint_order; it is nv x nv, so for large models pass
  // CalcMassMatrix a span of joints to get just their block
  if (plant.num_velocities > 12) {
    fmt::print("\n(mass matrix not printed: {} velocities)\n", plant.num_velocities);
    return 0;
  }
  const Eigen::MatrixXd M = mdlc::backend::CalcMassMatrix(plant, q);
  fmt::print("\nmass matrix at the default configuration ({0} x {0}):\n", M.rows());
  for (mdlc::JointId id : plant.joint_order) {
    const mdlc::backend::PlantJoint& joint = plant.joint(id);
    for (int k = 0; k < joint.nv; ++k) {
      fmt::print("  {:<20}", joint.nv == 1 ? joint.name : fmt::format("{}[{}]", joint.name, k));
      for (Eigen::Index c = 0; c < M.cols(); ++c) fmt::print(" {:>10.5f}", M(joint.v_start + k, c));
      fmt::print("\n");
    }
  }
  return 0;
}
