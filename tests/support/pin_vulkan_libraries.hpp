// SPDX-License-Identifier: MIT
// Under the sanitizers (make test-asan) a test program that makes a Vulkan instance pins the
// validation layer and lavapipe (RTLD_NODELETE) before it does. The Vulkan loader unloads both with
// the instance, and LeakSanitizer can name a module only while it is loaded. Unloaded, lavapipe also
// loses the globals that point to the blocks it allocates once per load (128 bytes from a
// pthread_once in vkEnumeratePhysicalDevices each time), which would then read as leaks of no
// module. What these libraries leak themselves is suppressed by name (tests/lsan.supp says why
// nothing of ours hides behind that). Outside AddressSanitizer builds this does nothing.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
#endif

namespace test_support {

inline void pinVulkanLibrariesForLeakSanitizer() {
#if defined(__SANITIZE_ADDRESS__)
    for (const char* library : {"libVkLayer_khronos_validation.so", "libvulkan_lvp.so"})
        dlopen(library, RTLD_NOW | RTLD_NODELETE);  // null where absent: nothing to pin
#endif
}

}  // namespace test_support
