// Comparing two renders of the same picture: how alike their structure is (SSIM), how bright and
// what colour each is on average. `voxflame bench fidelity` and the flat view's golden test judge
// voxflame's flat render against flam3-render's with these.
#pragma once

#include <glm/vec3.hpp>

#include "image_io.h"

namespace voxflame::core {

// The structural similarity index (Wang, Bovik, Sheikh & Simoncelli 2004) of the two images' luma
// (Rec. 709 weights on the display-encoded values, 0–1): local means, variances and covariance
// under an 11×11 Gaussian window of σ 1.5, C1 = 0.01², C2 = 0.03², averaged over every pixel whose
// window fits inside the image (all pixels of an image smaller than the window). 1 for identical
// images, near 0 for unrelated ones. Throws core::Error for images of different sizes or empty ones.
double ssimLuma(const ImageRGBA& a, const ImageRGBA& b);

// The mean linear luminance (the display values decoded as sRGB, Rec. 709 weights).
double meanLinearLuminance(const ImageRGBA& image);

// The mean of each channel's display-encoded value.
glm::dvec3 meanColor(const ImageRGBA& image);

}  // namespace voxflame::core
