#pragma once
// What a stereo depth camera (the depth of an RGB-D camera such as Intel's D400 series) gets
// wrong against the exact depth a render gives: noise that grows with the square of the depth,
// a scale bias, and no reading where only one of its two imagers sees the surface.

#include <cstdint>
#include <vector>

namespace viewer {

/// A stereo pair's depth errors (the default: exact depth).
///
/// A stereo camera measures the disparity d = f B / z (f its focal length in pixels, B the
/// baseline between its imagers) to a fraction of a pixel; an error in d is an error in 1/z of
/// the same relative size, so the depth's error grows as z^2: sigma_z = noise_at_1m * z^2 / 1 m^2
/// (Intel's "depth RMS error = z^2 x subpixel / (f x B)"). Here the noise is Gaussian on 1/z,
/// independent per pixel and per frame.
struct StereoDepthErrors {
  double noise_at_1m = 0.0;  ///< the depth's RMS error at 1 m (m)
  double scale = 1.0;        ///< every depth times this: the depth calibration's bias
  /// The pair's baseline (m), the second imager to the reference one's right along the image's
  /// rows: a surface just left of a nearer one is hidden from it and has no reading (+infinity),
  /// a band f B (1/z_near - 1/z_far) pixels wide. 0: no such band.
  double baseline = 0.0;
  bool exact() const { return noise_at_1m == 0.0 && scale == 1.0 && baseline == 0.0; }
};

/// `depth` (m along the axis, rows top first, +infinity where nothing is; `width` x `height`
/// pixels, vertical field of view `fov_y` rad) as the stereo camera `errors` would read it.
/// `key` draws the noise: the same key, the same noise. An empty `depth` (none rendered) stays
/// empty; one of another size than width x height is std::invalid_argument.
void applyStereoErrors(std::vector<float>& depth, int width, int height, double fov_y,
                       const StereoDepthErrors& errors, std::uint64_t key);

/// A key for one image: the seed of a run, which camera, and when (s of simulated time).
std::uint64_t depthNoiseKey(std::uint64_t seed, std::size_t camera, double time);

}  // namespace viewer
