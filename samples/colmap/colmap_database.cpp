// This file is part of opencv_essential, licensed under the Apache License, Version 2.0.
// See the LICENSE file at the top of the source tree.

#include "colmap/colmap_database.hpp"

#include "colmap/colmap_schema.hpp"

#include <cstring>

namespace essential_colmap {

namespace {

/** The blob of a (rows x cols, elementBytes each) matrix row, checked: its size must be
rows * cols * elementBytes. `what` names the row in the error. */
std::vector<unsigned char> matrixBlob(const SqliteStatement& row, int rowsColumn, int colsColumn,
                                      int dataColumn, std::size_t elementBytes,
                                      const std::string& what, std::int64_t& rows,
                                      std::int64_t& cols)
{
    rows = row.integer(rowsColumn);
    cols = row.integer(colsColumn);
    std::vector<unsigned char> data = row.blob(dataColumn);
    if (rows < 0 || cols < 0 || (rows > 0 && cols == 0))
        throw DatabaseError(what + ": invalid shape " + std::to_string(rows) + " x " +
                            std::to_string(cols));
    // rows * cols * elementBytes can wrap around (rows 768614336404564651, cols 6 and 4-byte
    // elements make 8 bytes): bound each factor by the blob's size first, so that a wrapped size
    // never matches a small blob and a huge row count never reaches an allocation.
    const std::uint64_t elements = data.size() / elementBytes;
    if (rows > 0 &&
        (static_cast<std::uint64_t>(cols) > elements ||
         static_cast<std::uint64_t>(rows) > elements / static_cast<std::uint64_t>(cols)))
        throw DatabaseError(what + ": blob of " + std::to_string(data.size()) +
                            " bytes, too small for " + std::to_string(rows) + " x " +
                            std::to_string(cols));
    const std::size_t expected =
        static_cast<std::size_t>(rows) * static_cast<std::size_t>(cols) * elementBytes;
    if (data.size() != expected)
        throw DatabaseError(what + ": blob of " + std::to_string(data.size()) + " bytes, " +
                            std::to_string(rows) + " x " + std::to_string(cols) + " needs " +
                            std::to_string(expected));
    return data;
}

} // namespace

ColmapDatabase::ColmapDatabase(const std::string& path, bool readOnly)
    : connection_(path, readOnly), schema_(checkColmapSchema(connection_))
{
}

std::map<std::int64_t, ColmapCamera> ColmapDatabase::cameras()
{
    SqliteStatement query(connection_, "SELECT camera_id, model, width, height, params, "
                                       "prior_focal_length FROM cameras");
    std::map<std::int64_t, ColmapCamera> out;
    while (query.step()) {
        ColmapCamera camera;
        camera.id = query.integer(0);
        camera.modelId = static_cast<int>(query.integer(1));
        camera.width = query.integer(2);
        camera.height = query.integer(3);
        const std::vector<unsigned char> params = query.blob(4);
        if (params.size() % sizeof(double) != 0)
            throw DatabaseError("camera " + std::to_string(camera.id) + ": params blob of " +
                                std::to_string(params.size()) + " bytes is not a list of float64");
        camera.params.resize(params.size() / sizeof(double));
        if (!params.empty()) std::memcpy(camera.params.data(), params.data(), params.size());
        camera.priorFocalLength = query.integer(5) != 0;
        out[camera.id] = camera;
    }
    return out;
}

std::map<std::int64_t, ColmapImage> ColmapDatabase::images()
{
    SqliteStatement query(connection_, "SELECT image_id, name, camera_id FROM images");
    std::map<std::int64_t, ColmapImage> out;
    while (query.step()) {
        ColmapImage image;
        image.id = query.integer(0);
        image.name = query.text(1);
        image.cameraId = query.integer(2);
        out[image.id] = image;
    }
    return out;
}

std::vector<cv::Point2f> ColmapDatabase::keypoints(std::int64_t imageId)
{
    SqliteStatement query(connection_, "SELECT rows, cols, data FROM keypoints WHERE image_id = ?");
    query.bind(1, imageId);
    std::vector<cv::Point2f> out;
    if (!query.step()) return out;
    const std::string what = "keypoints of image " + std::to_string(imageId);
    std::int64_t rows, cols;
    const std::vector<unsigned char> data =
        matrixBlob(query, 0, 1, 2, sizeof(float), what, rows, cols);
    if (rows == 0) return out;
    if (cols != 2 && cols != 4 && cols != 6)
        throw DatabaseError(what + ": " + std::to_string(cols) +
                            " columns (COLMAP stores 2, 4 or 6: x, y, then scale and orientation "
                            "or an affine shape)");
    out.resize(static_cast<std::size_t>(rows));
    const float* values = reinterpret_cast<const float*>(data.data());
    for (std::size_t i = 0; i < out.size(); ++i)
        out[i] = cv::Point2f(values[i * cols], values[i * cols + 1]);
    return out;
}

std::vector<std::int64_t> ColmapDatabase::matchedPairs()
{
    SqliteStatement query(connection_, "SELECT pair_id FROM matches ORDER BY pair_id");
    std::vector<std::int64_t> out;
    while (query.step())
        out.push_back(query.integer(0));
    return out;
}

std::vector<FeatureMatch> ColmapDatabase::matches(std::int64_t pairId)
{
    SqliteStatement query(connection_, "SELECT rows, cols, data FROM matches WHERE pair_id = ?");
    query.bind(1, pairId);
    std::vector<FeatureMatch> out;
    if (!query.step()) return out;
    const std::string what = "matches of pair " + std::to_string(pairId);
    std::int64_t rows, cols;
    const std::vector<unsigned char> data =
        matrixBlob(query, 0, 1, 2, sizeof(std::uint32_t), what, rows, cols);
    if (rows == 0) return out;
    if (cols != 2)
        throw DatabaseError(what + ": " + std::to_string(cols) + " columns, COLMAP stores 2");
    out.resize(static_cast<std::size_t>(rows));
    std::memcpy(out.data(), data.data(), data.size());
    return out;
}

std::map<std::int64_t, StoredGeometry> ColmapDatabase::storedGeometries()
{
    SqliteStatement query(connection_, "SELECT pair_id, config, rows FROM two_view_geometries");
    std::map<std::int64_t, StoredGeometry> out;
    while (query.step())
        out[query.integer(0)] =
            StoredGeometry{static_cast<int>(query.integer(1)), query.integer(2)};
    return out;
}

} // namespace essential_colmap
