// Sanitizer builds only: the Vulkan loader unloads driver and layer libraries at
// vkDestroyInstance, after which LeakSanitizer cannot name the module that allocated what those
// libraries keep for the process's life. Keeping them loaded lets tests/lsan.supp match them
// by library name, so leaks in Sightline's own code still fail the run.
#include <dlfcn.h>

extern "C" int dlclose(void*) {
  return 0;
}
