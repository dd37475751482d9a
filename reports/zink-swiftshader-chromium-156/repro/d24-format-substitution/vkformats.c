/* Which depth formats a Vulkan driver can sample (vkGetPhysicalDeviceFormatProperties,
 * optimal tiling); the few Vulkan declarations it needs are written out, so no Vulkan headers are
 * needed (libvulkan1 only). Plain C, no shadowcheck code. */
#include <stdio.h>
#include <stdint.h>
#include <dlfcn.h>
typedef struct { int sType; const void *pNext; uint32_t flags; const void *app; uint32_t nl; const char *const *l; uint32_t ne; const char *const *e; } ICI;
typedef struct { uint32_t lin, opt, buf; } FP;
typedef int (*CI)(const ICI *, const void *, void **);
typedef int (*EPD)(void *, uint32_t *, void **);
typedef void (*GFP)(void *, int, FP *);
typedef void *(*GIPA)(void *, const char *);
int main(void) {
    void *lib = dlopen("libvulkan.so.1", RTLD_NOW); if (!lib) return 2;
    GIPA gipa = (GIPA)dlsym(lib, "vkGetInstanceProcAddr");
    CI ci = (CI)gipa(NULL, "vkCreateInstance");
    ICI info = {1, 0, 0, 0, 0, 0, 0, 0}; void *inst = 0;
    if (ci(&info, 0, &inst)) { puts("vkCreateInstance failed"); return 2; }
    EPD epd = (EPD)gipa(inst, "vkEnumeratePhysicalDevices");
    GFP gfp = (GFP)gipa(inst, "vkGetPhysicalDeviceFormatProperties");
    uint32_t n = 4; void *pd[4]; epd(inst, &n, pd);
    const char *names[] = {"D16_UNORM", "X8_D24_UNORM_PACK32", "D32_SFLOAT", "S8_UINT", "D16_UNORM_S8_UINT", "D24_UNORM_S8_UINT", "D32_SFLOAT_S8_UINT"};
    for (uint32_t d = 0; d < n; d++)
        for (int f = 124; f <= 130; f++) { FP p = {0}; gfp(pd[d], f, &p);
            printf("device %u VK_FORMAT_%-20s optimal-tiling: sampled %s, depth attachment %s\n", d, names[f - 124], (p.opt & 1) ? "yes" : "no", (p.opt & 0x200) ? "yes" : "no"); }
    return 0;
}
