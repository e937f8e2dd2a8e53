// SPDX-License-Identifier: MIT
// tinygltf's implementation, compiled once, here. Its configuration macros (tinygltf 2.7) are
// compile definitions of the whole engine_assets target (CMakeLists.txt), because the header's
// inline code (TinyGLTF's constructor) depends on them in every file that includes it:
//   TINYGLTF_NO_STB_IMAGE / _WRITE: images are captured undecoded by our loader callback and
//     decoded by OpenImageIO after the checks (image_decode.cpp); stb is not linked.
//   TINYGLTF_NO_EXTERNAL_IMAGE: tinygltf never opens image files; we open them, confined to
//     the glTF's directory.
// TINYGLTF_ENABLE_DRACO is deliberately NOT defined: tinygltf 2.7 decodes Draco while parsing,
// without range checks, and rewrites the accessors' counts (see gltf_draco.hpp); we decode
// KHR_draco_mesh_compression ourselves. Debian's prebuilt libtinygltf (the TinyGLTF CMake
// target) is not linked: it is built without Draco and with stb_image.
// Compiled with -w (CMakeLists.txt): warnings in third-party code are not ours to fix.
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
