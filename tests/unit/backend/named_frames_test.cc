// Finding bodies and frames by name (backend/named_frames.h), the lookup
// behind the frame arguments of mdlc/dynamics.h and Python's jacobian().
#include "backend/named_frames.h"

#include <gtest/gtest.h>

#include "tests/unit/backend/backend_test_util.h"

namespace mdlc::backend {
namespace {

using ir::JointType;
using test_util::ModelBuilder;

class NamedFrames : public ::testing::Test {
 protected:
  void SetUp() override {
    ModelBuilder b("left");
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity() * 0.01;
    cup_ = b.AddBody("cup", 1, Eigen::Vector3d::Zero(), I);
    b.AddJoint("slide", JointType::Prismatic, ir::kWorldBody, cup_);
    // an MJCF site named after its body, and a frame named only here
    AddFrame(b, "cup", cup_, Transform::FromTranslation(Eigen::Vector3d(0, 0, 0.1)));
    AddFrame(b, "rim", cup_, Transform::FromTranslation(Eigen::Vector3d(0, 0, 0.2)));
    b.SetInstance(b.AddInstance("right"));
    const BodyId other = b.AddBody("cup", 1, Eigen::Vector3d::Zero(), I);
    b.AddJoint("slide", JointType::Prismatic, ir::kWorldBody, other);
    model_ = test_util::InstantiateOk(b.module());
    ASSERT_TRUE(model_);
  }
  static void AddFrame(ModelBuilder& b, std::string_view name, BodyId body, const Transform& X_BF) {
    ir::Frame frame;
    frame.name = b.module().Intern(name);
    frame.model = b.model();
    frame.body = b.BodyRef(body);
    frame.X_BF = X_BF;
    b.module().Add(frame);
  }
  FrameLookup Find(std::string_view name) const { return FindFrameByName(model_->plant, name); }

  BodyId cup_;
  std::optional<CompiledModel> model_;
};

TEST_F(NamedFrames, BodiesFramesAndTheWorld) {
  const FrameLookup world = Find("world");
  ASSERT_EQ(world.status, FrameLookupStatus::Found);
  EXPECT_EQ(world.frame.body, BodyId(size_t{0}));

  const FrameLookup rim = Find("left::rim");
  ASSERT_EQ(rim.status, FrameLookupStatus::Found);
  EXPECT_EQ(rim.frame.body, cup_);
  EXPECT_DOUBLE_EQ(rim.frame.X_BF.p.z(), 0.2);
  EXPECT_EQ(Find("rim").status, FrameLookupStatus::Found);  // one frame has that local name
}

TEST_F(NamedFrames, ABodysNameNamesItsOwnFrameOverASiteOfTheSameName) {
  const FrameLookup cup = Find("left::cup");
  ASSERT_EQ(cup.status, FrameLookupStatus::Found);
  EXPECT_EQ(cup.frame.body, cup_);
  EXPECT_TRUE(cup.frame.X_BF.IsIdentity());
}

TEST_F(NamedFrames, AmbiguousAndUnknownNames) {
  EXPECT_EQ(Find("cup").status, FrameLookupStatus::Ambiguous);  // a body in each instance
  EXPECT_EQ(Find("right::cup").status, FrameLookupStatus::Found);
  EXPECT_EQ(Find("handle").status, FrameLookupStatus::NotFound);
  EXPECT_EQ(Find("left::handle").status, FrameLookupStatus::NotFound);
  EXPECT_EQ(Find("").status, FrameLookupStatus::NotFound);
}

}  // namespace
}  // namespace mdlc::backend
