// The mesh reader's request and reply (issue 16, passes/mesh/io/mesh_wire.h):
// the reader reads the file and limits mdlc asked for, what the reader
// encodes the parent decodes to the same result, and the parent
// rejects every reply that is not well formed, since the child that wrote
// it may have been corrupted by the file it read.
#include "passes/mesh/io/mesh_wire.h"

#include <gtest/gtest.h>

#include <cstring>

namespace mdlc::mesh {
namespace {

MeshOrError Tetra() {
  auto m = std::make_shared<TriangleMesh>();
  m->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1.5}};
  m->triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return {std::move(m), {}};
}

std::optional<MeshOrError> Decode(const std::string& bytes, std::string* problem) {
  return DecodeMeshReply(bytes, problem);
}

// offsets of the mesh reply's fields: marker, version, kind, axes, counts
constexpr size_t kVersionAt = 8, kKindAt = 12, kUpAxisAt = 13, kTurnedAt = 14,
                 kVertexCountAt = 15, kTriangleCountAt = 23, kVerticesAt = 31;

TEST(MeshWireTest, AMeshComesBackAsSent) {  // issue 16
  const MeshOrError sent = Tetra();
  std::string problem;
  const std::optional<MeshOrError> got = Decode(EncodeMeshReply(sent), &problem);
  ASSERT_TRUE(got) << problem;
  ASSERT_TRUE(got->ok());
  EXPECT_EQ(got->mesh->vertices, sent.mesh->vertices);
  EXPECT_EQ(got->mesh->triangles, sent.mesh->triangles);
  EXPECT_EQ(got->mesh->declared_up, UpAxis::kNone);
  EXPECT_FALSE(got->mesh->turned_to_z_up);
}

TEST(MeshWireTest, TheFilesAxesComeBackAsSent) {  // issue 55, BEYOND-001
  for (const UpAxis up : {UpAxis::kX, UpAxis::kY, UpAxis::kZ}) {
    for (const bool turned : {false, true}) {
      MeshOrError sent = Tetra();
      auto mesh = std::make_shared<TriangleMesh>(*sent.mesh);
      mesh->declared_up = up;
      mesh->turned_to_z_up = turned;
      sent.mesh = mesh;
      std::string problem;
      const std::optional<MeshOrError> got = Decode(EncodeMeshReply(sent), &problem);
      ASSERT_TRUE(got) << problem;
      EXPECT_EQ(got->mesh->declared_up, up);
      EXPECT_EQ(got->mesh->turned_to_z_up, turned);
    }
  }
  // an axis or flag no reader sends
  for (const auto& [at, value] : {std::pair{kUpAxisAt, 4}, std::pair{kTurnedAt, 2}}) {
    std::string bytes = EncodeMeshReply(Tetra());
    bytes[at] = static_cast<char>(value);
    std::string problem;
    EXPECT_FALSE(Decode(bytes, &problem)) << at;
    EXPECT_NE(problem.find("up axis"), std::string::npos) << problem;
  }
}

TEST(MeshWireTest, TheFilesColorsComeBackAsSent) {  // issue 58, BEYOND-001
  MeshOrError sent = Tetra();
  auto mesh = std::make_shared<TriangleMesh>(*sent.mesh);
  mesh->colors = {{0, {0.9, 0.1, 0.1, 1}}, {3, {0.1, 0.8, 0.2, 0.5}}};
  sent.mesh = mesh;
  std::string problem;
  const std::optional<MeshOrError> got = Decode(EncodeMeshReply(sent), &problem);
  ASSERT_TRUE(got) << problem;
  EXPECT_EQ(got->mesh->colors, mesh->colors);
  EXPECT_EQ(got->mesh->triangles, mesh->triangles);
  // runs out of order, past the last triangle, or with a channel outside [0, 1]
  const std::vector<std::vector<TriangleColor>> bad = {
      {{1, {1, 0, 0, 1}}},
      {{0, {1, 0, 0, 1}}, {0, {0, 1, 0, 1}}},
      {{0, {1, 0, 0, 1}}, {4, {0, 1, 0, 1}}},
      {{0, {1.5, 0, 0, 1}}}};
  for (const std::vector<TriangleColor>& colors : bad) {
    mesh->colors = colors;
    EXPECT_FALSE(Decode(EncodeMeshReply(sent), &problem)) << colors.size();
    EXPECT_NE(problem.find("colour run"), std::string::npos) << problem;
  }
}

TEST(MeshWireTest, AnErrorComesBackWithItsLimitFlag) {  // issue 16
  for (const bool over_limit : {false, true}) {
    const MeshOrError sent{nullptr, "mesh file 'a.obj' holds no triangles", over_limit};
    std::string problem;
    const std::optional<MeshOrError> got = Decode(EncodeMeshReply(sent), &problem);
    ASSERT_TRUE(got) << problem;
    EXPECT_FALSE(got->ok());
    EXPECT_EQ(got->error, sent.error);
    EXPECT_EQ(got->over_limit, over_limit);
  }
}

TEST(MeshWireTest, EveryTruncationIsRejected) {  // issue 16
  for (const MeshOrError& sent : {Tetra(), MeshOrError{nullptr, "cannot read", false}}) {
    const std::string bytes = EncodeMeshReply(sent);
    for (size_t n = 0; n < bytes.size(); ++n) {
      std::string problem;
      EXPECT_FALSE(Decode(bytes.substr(0, n), &problem)) << "accepted " << n << " bytes";
      EXPECT_FALSE(problem.empty());
    }
  }
}

TEST(MeshWireTest, ExtraBytesAreRejected) {  // issue 16
  std::string problem;
  EXPECT_FALSE(Decode(EncodeMeshReply(Tetra()) + '\0', &problem));
  EXPECT_FALSE(Decode(EncodeMeshReply({nullptr, "x", false}) + 'y', &problem));
}

TEST(MeshWireTest, AnotherMarkerOrVersionOrKindIsRejected) {  // issue 16
  const std::string good = EncodeMeshReply(Tetra());
  std::string problem;
  std::string bytes = good;
  bytes[0] = 'X';
  EXPECT_FALSE(Decode(bytes, &problem));
  bytes = good;
  bytes[kVersionAt] = static_cast<char>(kMeshWireVersion + 1);
  EXPECT_FALSE(Decode(bytes, &problem));
  EXPECT_NE(problem.find("version"), std::string::npos) << problem;
  bytes = good;
  bytes[kKindAt] = 7;
  EXPECT_FALSE(Decode(bytes, &problem));
}

TEST(MeshWireTest, CountsThatDoNotFitAreRejected) {  // issue 16
  const std::string good = EncodeMeshReply(Tetra());
  for (const size_t at : {kVertexCountAt, kTriangleCountAt}) {
    // counts so large that multiplying them by an item's size overflows
    for (const uint64_t count : {uint64_t{5}, uint64_t{1} << 62, ~uint64_t{0}}) {
      std::string bytes = good;
      std::memcpy(bytes.data() + at, &count, sizeof count);
      std::string problem;
      EXPECT_FALSE(Decode(bytes, &problem)) << "count " << count << " at " << at;
    }
  }
}

TEST(MeshWireTest, ATriangleNamingAMissingVertexIsRejected) {  // issue 16
  const std::string good = EncodeMeshReply(Tetra());
  const size_t first_index = kVerticesAt + 4 * 3 * sizeof(double);
  for (const int32_t index : {4, -1}) {
    std::string bytes = good;
    std::memcpy(bytes.data() + first_index, &index, sizeof index);
    std::string problem;
    EXPECT_FALSE(Decode(bytes, &problem)) << index;
    EXPECT_NE(problem.find("names vertex"), std::string::npos) << problem;
  }
}

TEST(MeshWireTest, AMeshWithoutVerticesOrAnEmptyErrorIsRejected) {  // issue 16
  auto empty = std::make_shared<TriangleMesh>();
  std::string problem;
  EXPECT_FALSE(Decode(EncodeMeshReply({empty, {}}), &problem));
  EXPECT_FALSE(Decode(EncodeMeshReply({nullptr, "", false}), &problem));
}

TEST(MeshWireTest, PointsWithoutTrianglesTravel) {  // issue 62: the caller takes their hull
  auto points = std::make_shared<TriangleMesh>();
  points->vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  std::string problem;
  const auto got = Decode(EncodeMeshReply({points, {}}), &problem);
  ASSERT_TRUE(got) << problem;
  ASSERT_TRUE(got->ok()) << got->error;
  EXPECT_EQ(got->mesh->vertices, points->vertices);
  EXPECT_TRUE(got->mesh->triangles.empty());
}

std::vector<std::string_view> Views(const std::vector<std::string>& args) {
  return {args.begin(), args.end()};
}

TEST(MeshWireTest, ARequestCarriesThePathAndEveryLimit) {  // issue 16
  Limits sent;
  sent.mesh_vertices = 3;
  sent.file_size = 12345;
  for (const ColladaUpAxis collada : {ColladaUpAxis::kAsWritten, ColladaUpAxis::kApply}) {
    const std::vector<std::string> request =
        EncodeMeshRequest("dir/a mesh.obj", sent, MeshAxes{collada});
    Limits got;
    MeshAxes axes{collada == ColladaUpAxis::kApply ? ColladaUpAxis::kAsWritten
                                                   : ColladaUpAxis::kApply};
    std::string path;
    EXPECT_EQ(DecodeMeshRequest(Views(request), &path, &got, &axes), std::nullopt);
    EXPECT_EQ(path, "dir/a mesh.obj");
    EXPECT_EQ(axes.collada, collada);
    for (const LimitInfo& l : AllLimits()) EXPECT_EQ(got.*l.field, sent.*l.field) << l.name;
  }
}

TEST(MeshWireTest, AMalformedRequestIsRefused) {  // issue 16
  const std::vector<std::vector<std::string>> bad = {
      {"a.obj"}, {"--"}, {"--", "a.obj", "b.obj"}, {"no-such-limit=1", "--", "a.obj"},
      {"collada-up-axis=sideways", "--", "a.obj"}};
  for (const std::vector<std::string>& request : bad) {
    Limits limits;
    MeshAxes axes;
    std::string path;
    const std::optional<std::string> problem =
        DecodeMeshRequest(Views(request), &path, &limits, &axes);
    ASSERT_TRUE(problem) << request.front();
    EXPECT_FALSE(problem->empty());
  }
}

}  // namespace
}  // namespace mdlc::mesh
