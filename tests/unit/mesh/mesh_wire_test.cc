// The mesh reader's request and reply (issue 16, passes/mesh/mesh_wire.h):
// the reader reads the file and limits mdlc asked for, what the reader
// encodes the parent decodes to the same result, and the parent
// rejects every reply that is not well formed, since the child that wrote
// it may have been corrupted by the file it read.
#include "passes/mesh/mesh_wire.h"

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

// offsets of the mesh reply's fields: marker, version, kind, counts
constexpr size_t kVersionAt = 8, kKindAt = 12, kVertexCountAt = 13, kTriangleCountAt = 21,
                 kVerticesAt = 29;

TEST(MeshWireTest, AMeshComesBackAsSent) {  // issue 16
  const MeshOrError sent = Tetra();
  std::string problem;
  const std::optional<MeshOrError> got = Decode(EncodeMeshReply(sent), &problem);
  ASSERT_TRUE(got) << problem;
  ASSERT_TRUE(got->ok());
  EXPECT_EQ(got->mesh->vertices, sent.mesh->vertices);
  EXPECT_EQ(got->mesh->triangles, sent.mesh->triangles);
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

TEST(MeshWireTest, AMeshWithoutTrianglesOrAnEmptyErrorIsRejected) {  // issue 16
  auto empty = std::make_shared<TriangleMesh>();
  empty->vertices = {{0, 0, 0}};
  std::string problem;
  EXPECT_FALSE(Decode(EncodeMeshReply({empty, {}}), &problem));
  EXPECT_FALSE(Decode(EncodeMeshReply({nullptr, "", false}), &problem));
}

std::vector<std::string_view> Views(const std::vector<std::string>& args) {
  return {args.begin(), args.end()};
}

TEST(MeshWireTest, ARequestCarriesThePathAndEveryLimit) {  // issue 16
  Limits sent;
  sent.mesh_vertices = 3;
  sent.file_size = 12345;
  const std::vector<std::string> request = EncodeMeshRequest("dir/a mesh.obj", sent);
  Limits got;
  std::string path;
  EXPECT_EQ(DecodeMeshRequest(Views(request), &path, &got), std::nullopt);
  EXPECT_EQ(path, "dir/a mesh.obj");
  for (const LimitInfo& l : AllLimits()) EXPECT_EQ(got.*l.field, sent.*l.field) << l.name;
}

TEST(MeshWireTest, AMalformedRequestIsRefused) {  // issue 16
  const std::vector<std::vector<std::string>> bad = {
      {"a.obj"}, {"--"}, {"--", "a.obj", "b.obj"}, {"no-such-limit=1", "--", "a.obj"}};
  for (const std::vector<std::string>& request : bad) {
    Limits limits;
    std::string path;
    const std::optional<std::string> problem = DecodeMeshRequest(Views(request), &path, &limits);
    ASSERT_TRUE(problem) << request.front();
    EXPECT_FALSE(problem->empty());
  }
}

}  // namespace
}  // namespace mdlc::mesh
