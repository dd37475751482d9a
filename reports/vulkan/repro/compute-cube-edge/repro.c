/* Standalone reproducer: cube map edge handling of a LINEAR depth-compare lookup, compute stage vs.
 * fragment stage, on one Vulkan driver (the one VK_ICD_FILENAMES names).
 *
 * Build: glslangValidator --quiet -V -S comp -o comp.spv comp.glsl (and frag, vert; comp_nc.spv and
 *        frag_nc.spv with -DNOCOMPARE) && gcc -std=c99 -O1 -Wall -o repro repro.c -lvulkan
 *        (build.sh does all of it and runs every variant on both drivers, writing output.txt)
 * Run:   VK_ICD_FILENAMES=/usr/lib/chromium/vk_swiftshader_icd.json \
 *        VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation ./repro [options]
 *
 * What it checks. A VK_FORMAT_D32_SFLOAT cube image, 2x2 texels per face, 2 mip levels; layers
 * (+X, -X, +Y, -Y, +Z, -Z), level 0 row-major: +X = [0.9, 0.2, 0.9, 0.2] (column 0 is 0.9, column 1
 * is 0.2), -X = 0.3, +Y = 0.85, -Y = 0.75, +Z = 0.9, -Z = 0.65; level 1 = [0.2, 0.3, 0.85, 0.75, 0.9,
 * 0.65]. A CUBE view of both levels; a sampler with LINEAR mag/min filter, mipmapMode NEAREST,
 * CLAMP_TO_EDGE, compareEnable, compareOp LESS_OR_EQUAL, LOD range [-1000, 1000]. The lookup
 * texture(samplerCubeShadow, vec4(1.0, -0.0, 0.9, 0.5)) at level 0 (magnification), done once in a
 * fragment shader (1x1 framebuffer, full-screen triangle) and once in a compute shader (one
 * invocation writing a storage buffer).
 *
 * The expected value, from the Vulkan 1.3 spec. "Cube Map Face Selection": major axis +X, so
 * sc = -rz = -0.9, tc = -ry = 0, ma = 1; s = (sc/|ma| + 1)/2 = 0.05, t = 0.5. Texel space (2x2
 * face): u = 0.1, v = 1.0. LINEAR ("Texel Filtering"): i0 = floor(u - 0.5) = -1, i1 = 0, alpha = 0.6;
 * j0 = 0, j1 = 1, beta = 0.5. Column i0 = -1 lies beyond the face's s = 0 edge, which for +X is the
 * +Z side, so "Cube Map Edge Handling" (in "Texel Input Operations") applies:
 *   "If the texel lies beyond the selected cube map face in either only i or only j, then the
 *    coordinates (i,j) and the array layer l are transformed to select the adjacent texel from the
 *    appropriate neighboring face."
 * and "Wrapping Operation": "Cube images ignore the wrap modes specified in the sampler. Instead, if
 * VK_FILTER_NEAREST is used within a mip level then VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE is used,
 * and if VK_FILTER_LINEAR is used within a mip level then sampling at the edges is performed as
 * described earlier in the Cube map edge handling section."
 * So the footprint is two +Z texels (0.9) and two +X column-0 texels (0.9): all four pass
 * 0.5 <= 0.9, and the result is 1 (the "Depth Compare Operation" lets a LINEAR compare result be
 * implementation-dependent, but "should be proportional to, or a weighted average of, the number
 * of comparison passes or failures": 4 of 4 pass). Readings without edge handling, for comparison:
 *   clamp column -1 to column 0 within +X (0.9):          compare 1     no-compare 0.9
 *   wrap column -1 to column 1 within +X (0.2):           compare 0.6   no-compare 0.62
 *   a border / zero texel for column -1 (0):              compare 0.6   no-compare 0.54
 *   column -1 from a wrong face: -X 0.3 -> 0.6 / 0.66; -Z 0.65 -> 1 / 0.8; +Y 0.85 -> 1 / 0.87
 * (no-compare = 0.4 * x + 0.6 * 0.9 for a column -1 texel value x; compare = 0.6 when x < 0.5).
 *
 * Options (the variants): --repeat (addressMode REPEAT: must not matter for a cube), --corner
 * (direction (1, -0.9, 0.9): s = 0.05, t = 0.95 on +X, the +X/+Z/-Y corner), --nearest (NEAREST
 * filter: no edge handling involved), --levels=1 (a 1-level image), --runs=N (N compute dispatches,
 * each its own submission, before the draw), --nocompare (compareEnable = VK_FALSE and samplerCube:
 * returns the filtered depth, which shows which texel value was used across the edge),
 * --frag-first (the draw before the first dispatch). Order otherwise: N dispatches, the draw, one
 * more dispatch, all on the same image and sampler.
 *
 * Prints each result with %.9g, the expected value and PASS/FAIL per stage. Exit status: 1 when
 * a compute result is wrong, 0 when every compute result is right, 2 when setup fails.
 */
#include <vulkan/vulkan.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int opt_repeat, opt_corner, opt_nearest, opt_levels = 2, opt_runs = 1, opt_nocompare, opt_frag_first;

static void die(const char *what) {
    fprintf(stderr, "setup failed: %s\n", what);
    exit(2);
}
static void check_vk(VkResult r, const char *what) {
    if (r != VK_SUCCESS) {
        fprintf(stderr, "setup failed: %s returned VkResult %d\n", what, (int)r);
        exit(2);
    }
}
#define CHECK(call) check_vk((call), #call)

static VkInstance instance;
static VkPhysicalDevice physical;
static VkDevice device;
static VkQueue queue;
static uint32_t family;
static VkPhysicalDeviceMemoryProperties memory;
static VkCommandPool cmd_pool;

/* Validation messages (VK_EXT_debug_utils, where the loader or a layer offers it). */
static int n_messages;
static VKAPI_ATTR VkBool32 VKAPI_CALL on_message(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                 VkDebugUtilsMessageTypeFlagsEXT type,
                                                 const VkDebugUtilsMessengerCallbackDataEXT *data, void *user) {
    (void)user;
    if (severity < VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT) return VK_FALSE;
    if (!(type & (VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT))) {
        /* General messages, e.g. the loader's note that VK_INSTANCE_LAYERS added the layer. */
        fprintf(stderr, "(general message, not counted) %s\n", data->pMessage);
        return VK_FALSE;
    }
    n_messages++;
    fprintf(stderr, "VALIDATION: %s\n", data->pMessage);
    return VK_FALSE;
}

static uint32_t memory_type(uint32_t bits, VkMemoryPropertyFlags flags) {
    for (uint32_t i = 0; i < memory.memoryTypeCount; i++)
        if ((bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & flags) == flags) return i;
    die("no suitable memory type");
    return 0;
}
static VkDeviceMemory allocate(VkMemoryRequirements req, VkMemoryPropertyFlags flags) {
    VkMemoryAllocateInfo ai = {VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = memory_type(req.memoryTypeBits, flags);
    VkDeviceMemory m;
    CHECK(vkAllocateMemory(device, &ai, NULL, &m));
    return m;
}

struct host_buffer {
    VkBuffer buffer;
    void *ptr;
};
static struct host_buffer host_buffer(VkDeviceSize size, VkBufferUsageFlags usage) {
    struct host_buffer b;
    VkBufferCreateInfo ci = {VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    ci.size = size;
    ci.usage = usage;
    ci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    CHECK(vkCreateBuffer(device, &ci, NULL, &b.buffer));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device, b.buffer, &req);
    VkDeviceMemory m = allocate(req, VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    CHECK(vkBindBufferMemory(device, b.buffer, m, 0));
    CHECK(vkMapMemory(device, m, 0, VK_WHOLE_SIZE, 0, &b.ptr));
    return b;
}
static void bind_image(VkImage image) {
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device, image, &req);
    CHECK(vkBindImageMemory(device, image, allocate(req, 0), 0));
}

static int has_extension(const VkExtensionProperties *e, uint32_t n, const char *name) {
    for (uint32_t i = 0; i < n; i++)
        if (strcmp(e[i].extensionName, name) == 0) return 1;
    return 0;
}

static void make_device(void) {
    uint32_t loader = VK_API_VERSION_1_0;
    CHECK(vkEnumerateInstanceVersion(&loader));
    VkApplicationInfo app = {VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "compute-cube-edge";
    app.apiVersion = loader < VK_API_VERSION_1_3 ? loader : VK_API_VERSION_1_3;
    uint32_t ne = 0;
    CHECK(vkEnumerateInstanceExtensionProperties(NULL, &ne, NULL));
    VkExtensionProperties *exts = calloc(ne ? ne : 1, sizeof *exts);
    if (!exts) die("out of memory");
    CHECK(vkEnumerateInstanceExtensionProperties(NULL, &ne, exts));
    int debug_utils = has_extension(exts, ne, VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
    free(exts);
    const char *ext_name = VK_EXT_DEBUG_UTILS_EXTENSION_NAME;
    VkDebugUtilsMessengerCreateInfoEXT mci = {VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    mci.messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    mci.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                      VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    mci.pfnUserCallback = on_message;
    VkInstanceCreateInfo ici = {VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ici.pApplicationInfo = &app;
    if (debug_utils) {
        ici.enabledExtensionCount = 1;
        ici.ppEnabledExtensionNames = &ext_name;
        ici.pNext = &mci; /* also covers vkCreateInstance / vkDestroyInstance */
    }
    CHECK(vkCreateInstance(&ici, NULL, &instance));
    if (debug_utils) {
        PFN_vkCreateDebugUtilsMessengerEXT create =
            (PFN_vkCreateDebugUtilsMessengerEXT)vkGetInstanceProcAddr(instance, "vkCreateDebugUtilsMessengerEXT");
        VkDebugUtilsMessengerEXT messenger;
        if (create) CHECK(create(instance, &mci, NULL, &messenger));
    }

    VkPhysicalDevice all[16];
    uint32_t n = 16;
    VkResult r = vkEnumeratePhysicalDevices(instance, &n, all);
    if (r != VK_SUCCESS && r != VK_INCOMPLETE) check_vk(r, "vkEnumeratePhysicalDevices");
    if (n == 0) die("no Vulkan physical device (is VK_ICD_FILENAMES right?)");
    physical = all[0];
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(physical, &props);
    uint32_t api = props.apiVersion;
    printf("VK_DEVICE: %s\nVK_API_VERSION: %u.%u.%u\n", props.deviceName, VK_API_VERSION_MAJOR(api),
           VK_API_VERSION_MINOR(api), VK_API_VERSION_PATCH(api));
    if (api >= VK_API_VERSION_1_2 && app.apiVersion >= VK_API_VERSION_1_2) {
        VkPhysicalDeviceDriverProperties dp = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
        VkPhysicalDeviceProperties2 p2 = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2};
        p2.pNext = &dp;
        vkGetPhysicalDeviceProperties2(physical, &p2);
        printf("VK_DRIVER: %s%s%s (driverID %d)\n", dp.driverName, dp.driverInfo[0] ? " " : "", dp.driverInfo,
               (int)dp.driverID);
    } else {
        printf("VK_DRIVER: driver version 0x%x\n", props.driverVersion);
    }
    vkGetPhysicalDeviceMemoryProperties(physical, &memory);

    VkFormatProperties fp;
    vkGetPhysicalDeviceFormatProperties(physical, VK_FORMAT_D32_SFLOAT, &fp);
    VkFormatFeatureFlags need = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT;
    if ((fp.optimalTilingFeatures & need) != need) die("D32_SFLOAT lacks SAMPLED_IMAGE / TRANSFER_DST");
    if (opt_nocompare && !opt_nearest && !(fp.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
        die("D32_SFLOAT lacks SAMPLED_IMAGE_FILTER_LINEAR (needed by --nocompare with LINEAR)");

    VkQueueFamilyProperties families[16];
    uint32_t nf = 16;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &nf, families);
    const VkQueueFlags want = VK_QUEUE_GRAPHICS_BIT | VK_QUEUE_COMPUTE_BIT;
    family = nf;
    for (uint32_t i = 0; i < nf && family == nf; i++)
        if ((families[i].queueFlags & want) == want) family = i;
    if (family == nf) die("no graphics+compute queue");
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qci = {VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qci.queueFamilyIndex = family;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    VkDeviceCreateInfo dci = {VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    CHECK(vkCreateDevice(physical, &dci, NULL, &device));
    vkGetDeviceQueue(device, family, 0, &queue);
    VkCommandPoolCreateInfo cpi = {VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    cpi.queueFamilyIndex = family;
    CHECK(vkCreateCommandPool(device, &cpi, NULL, &cmd_pool));
}

static VkShaderModule shader_module(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "setup failed: cannot read %s (run from this directory: sh build.sh)\n", path);
        exit(2);
    }
    static uint32_t words[1 << 16];
    size_t n = fread(words, 1, sizeof words, f);
    fclose(f);
    if (n == 0 || n % 4 != 0 || n == sizeof words) die("a SPIR-V file is empty, truncated or too large");
    VkShaderModuleCreateInfo ci = {VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    ci.codeSize = n;
    ci.pCode = words;
    VkShaderModule m;
    CHECK(vkCreateShaderModule(device, &ci, NULL, &m));
    return m;
}

static VkCommandBuffer begin(void) {
    VkCommandBufferAllocateInfo cai = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    cai.commandPool = cmd_pool;
    cai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    cai.commandBufferCount = 1;
    VkCommandBuffer cmd;
    CHECK(vkAllocateCommandBuffers(device, &cai, &cmd));
    VkCommandBufferBeginInfo bi = {VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
    bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    CHECK(vkBeginCommandBuffer(cmd, &bi));
    return cmd;
}
/* Ends, submits and waits for cmd; host reads after this see what the barrier to HOST made available. */
static void submit(VkCommandBuffer cmd) {
    CHECK(vkEndCommandBuffer(cmd));
    VkFenceCreateInfo fci = {VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    CHECK(vkCreateFence(device, &fci, NULL, &fence));
    VkSubmitInfo si = {VK_STRUCTURE_TYPE_SUBMIT_INFO};
    si.commandBufferCount = 1;
    si.pCommandBuffers = &cmd;
    CHECK(vkQueueSubmit(queue, 1, &si, fence));
    CHECK(vkWaitForFences(device, 1, &fence, VK_TRUE, 120000000000ull));
    vkDestroyFence(device, fence, NULL);
    vkFreeCommandBuffers(device, cmd_pool, 1, &cmd);
}

static void host_barrier(VkCommandBuffer cmd, VkPipelineStageFlags src_stage, VkAccessFlags src_access) {
    VkMemoryBarrier mb = {VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    mb.srcAccessMask = src_access;
    mb.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, src_stage, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &mb, 0, NULL, 0, NULL);
}

/* Level 0: per face 2x2, row-major (x fastest); level 1: per face 1x1. Layers +X -X +Y -Y +Z -Z. */
static const float LEVEL0[6][4] = {
    {0.9f, 0.2f, 0.9f, 0.2f}, {0.3f, 0.3f, 0.3f, 0.3f}, {0.85f, 0.85f, 0.85f, 0.85f},
    {0.75f, 0.75f, 0.75f, 0.75f}, {0.9f, 0.9f, 0.9f, 0.9f}, {0.65f, 0.65f, 0.65f, 0.65f},
};
static const float LEVEL1[6] = {0.2f, 0.3f, 0.85f, 0.75f, 0.9f, 0.65f};

int main(int argc, char **argv) {
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--repeat")) opt_repeat = 1;
        else if (!strcmp(argv[i], "--corner")) opt_corner = 1;
        else if (!strcmp(argv[i], "--nearest")) opt_nearest = 1;
        else if (!strcmp(argv[i], "--levels=1")) opt_levels = 1;
        else if (!strncmp(argv[i], "--runs=", 7)) opt_runs = atoi(argv[i] + 7);
        else if (!strcmp(argv[i], "--nocompare")) opt_nocompare = 1;
        else if (!strcmp(argv[i], "--frag-first")) opt_frag_first = 1;
        else {
            fprintf(stderr, "usage: %s [--repeat] [--corner] [--nearest] [--levels=1] [--runs=N] [--nocompare] [--frag-first]\n", argv[0]);
            return 2;
        }
    }
    if (opt_runs < 1 || opt_runs > 1000) die("--runs must be 1..1000");
    const float P[4] = {1.0f, opt_corner ? -0.9f : -0.0f, 0.9f, 0.5f}; /* direction, Dref */

    /* Expected (see the header comment): compare: 1 everywhere. No compare: the LINEAR footprint's
     * weighted depth, 0.9 on the edge; at the corner 0.72 + 0.16 * c for the corner texel c, which
     * "should" be the average (0.9 + 0.9 + 0.75) / 3 = 0.85 but "may" be another method keeping it
     * within the three values: [0.84, 0.864]. NEAREST: texel (0, 1) of +X, 0.9 (compare 1). */
    double lo, hi;
    if (!opt_nocompare) lo = hi = 1.0;
    else if (opt_corner && !opt_nearest) lo = 0.72 + 0.16 * 0.75, hi = 0.72 + 0.16 * 0.9;
    else lo = hi = 0.9;
    const double tol = opt_nocompare ? 1e-3 : 1e-6; /* filtering-weight precision; a compare result of 1 is exact */

    make_device();
    printf("variant:   %s%s%s%s%s, %d level%s, runs=%d%s\n", opt_nearest ? "NEAREST" : "LINEAR",
           opt_nocompare ? " no-compare (filtered depth)" : " compare LESS_OR_EQUAL",
           opt_repeat ? ", REPEAT" : ", CLAMP_TO_EDGE", opt_corner ? ", corner direction (1, -0.9, 0.9)" : ", edge direction (1, -0, 0.9)",
           "", opt_levels, opt_levels == 1 ? "" : "s", opt_runs, opt_frag_first ? ", fragment first" : "");
    if (lo == hi) printf("expected:  %.9g (both stages)\n", lo);
    else printf("expected:  in [%.9g, %.9g] (both stages; the corner texel's method is implementation's choice)\n", lo, hi);

    /* The cube image, its view and the sampler. */
    VkImageCreateInfo ici = {VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ici.flags = VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT;
    ici.imageType = VK_IMAGE_TYPE_2D;
    ici.format = VK_FORMAT_D32_SFLOAT;
    ici.extent = (VkExtent3D){2, 2, 1};
    ici.mipLevels = (uint32_t)opt_levels;
    ici.arrayLayers = 6;
    ici.samples = VK_SAMPLE_COUNT_1_BIT;
    ici.tiling = VK_IMAGE_TILING_OPTIMAL;
    ici.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    ici.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImage image;
    CHECK(vkCreateImage(device, &ici, NULL, &image));
    bind_image(image);
    VkImageViewCreateInfo vci = {VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = image;
    vci.viewType = VK_IMAGE_VIEW_TYPE_CUBE;
    vci.format = VK_FORMAT_D32_SFLOAT;
    vci.subresourceRange = (VkImageSubresourceRange){VK_IMAGE_ASPECT_DEPTH_BIT, 0, (uint32_t)opt_levels, 0, 6};
    VkImageView view;
    CHECK(vkCreateImageView(device, &vci, NULL, &view));
    VkSamplerCreateInfo sci = {VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    sci.magFilter = sci.minFilter = opt_nearest ? VK_FILTER_NEAREST : VK_FILTER_LINEAR;
    sci.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
    sci.addressModeU = sci.addressModeV = sci.addressModeW =
        opt_repeat ? VK_SAMPLER_ADDRESS_MODE_REPEAT : VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    sci.mipLodBias = 0.0f;
    sci.compareEnable = opt_nocompare ? VK_FALSE : VK_TRUE;
    sci.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    sci.minLod = -1000.0f;
    sci.maxLod = 1000.0f;
    sci.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
    VkSampler sampler;
    CHECK(vkCreateSampler(device, &sci, NULL, &sampler));

    /* One descriptor set for both pipelines: the sampled cube at binding 0 (fragment and compute),
     * the compute result buffer at binding 1; the push constant (direction, Dref) in both stages. */
    struct host_buffer out = host_buffer(16, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
    VkDescriptorSetLayoutBinding bindings[2] = {
        {0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT, NULL},
        {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_COMPUTE_BIT, NULL},
    };
    VkDescriptorSetLayoutCreateInfo slci = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    slci.bindingCount = 2;
    slci.pBindings = bindings;
    VkDescriptorSetLayout set_layout;
    CHECK(vkCreateDescriptorSetLayout(device, &slci, NULL, &set_layout));
    const VkShaderStageFlags pc_stages = VK_SHADER_STAGE_FRAGMENT_BIT | VK_SHADER_STAGE_COMPUTE_BIT;
    VkPushConstantRange pc = {pc_stages, 0, sizeof P};
    VkPipelineLayoutCreateInfo plci = {VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    plci.setLayoutCount = 1;
    plci.pSetLayouts = &set_layout;
    plci.pushConstantRangeCount = 1;
    plci.pPushConstantRanges = &pc;
    VkPipelineLayout layout;
    CHECK(vkCreatePipelineLayout(device, &plci, NULL, &layout));
    VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1}};
    VkDescriptorPoolCreateInfo dpci = {VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    dpci.maxSets = 1;
    dpci.poolSizeCount = 2;
    dpci.pPoolSizes = sizes;
    VkDescriptorPool pool;
    CHECK(vkCreateDescriptorPool(device, &dpci, NULL, &pool));
    VkDescriptorSetAllocateInfo dai = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    dai.descriptorPool = pool;
    dai.descriptorSetCount = 1;
    dai.pSetLayouts = &set_layout;
    VkDescriptorSet set;
    CHECK(vkAllocateDescriptorSets(device, &dai, &set));
    VkDescriptorImageInfo ii = {sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkDescriptorBufferInfo bi = {out.buffer, 0, 16};
    VkWriteDescriptorSet writes[2] = {{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}, {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}};
    writes[0].dstSet = set;
    writes[0].dstBinding = 0;
    writes[0].descriptorCount = 1;
    writes[0].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    writes[0].pImageInfo = &ii;
    writes[1].dstSet = set;
    writes[1].dstBinding = 1;
    writes[1].descriptorCount = 1;
    writes[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    writes[1].pBufferInfo = &bi;
    vkUpdateDescriptorSets(device, 2, writes, 0, NULL);

    /* The compute pipeline. */
    VkComputePipelineCreateInfo cpci = {VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    cpci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    cpci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    cpci.stage.module = shader_module(opt_nocompare ? "comp_nc.spv" : "comp.spv");
    cpci.stage.pName = "main";
    cpci.layout = layout;
    VkPipeline compute;
    CHECK(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &cpci, NULL, &compute));

    /* The colour target (1x1 RGBA32F, cleared to -1, left in TRANSFER_SRC_OPTIMAL), render pass,
     * framebuffer and graphics pipeline. */
    VkImageCreateInfo tci = {VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    tci.imageType = VK_IMAGE_TYPE_2D;
    tci.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    tci.extent = (VkExtent3D){1, 1, 1};
    tci.mipLevels = 1;
    tci.arrayLayers = 1;
    tci.samples = VK_SAMPLE_COUNT_1_BIT;
    tci.tiling = VK_IMAGE_TILING_OPTIMAL;
    tci.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    VkImage color;
    CHECK(vkCreateImage(device, &tci, NULL, &color));
    bind_image(color);
    VkImageViewCreateInfo cvci = {VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    cvci.image = color;
    cvci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    cvci.format = tci.format;
    cvci.subresourceRange = (VkImageSubresourceRange){VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView color_view;
    CHECK(vkCreateImageView(device, &cvci, NULL, &color_view));
    VkAttachmentDescription att = {0};
    att.format = tci.format;
    att.samples = VK_SAMPLE_COUNT_1_BIT;
    att.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
    att.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    att.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
    att.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    att.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    att.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    VkAttachmentReference ref = {0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription sub = {0};
    sub.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    sub.colorAttachmentCount = 1;
    sub.pColorAttachments = &ref;
    VkSubpassDependency dep = {0};
    dep.srcSubpass = 0;
    dep.dstSubpass = VK_SUBPASS_EXTERNAL;
    dep.srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
    dep.srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
    dep.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dep.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    VkRenderPassCreateInfo rci = {VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
    rci.attachmentCount = 1;
    rci.pAttachments = &att;
    rci.subpassCount = 1;
    rci.pSubpasses = &sub;
    rci.dependencyCount = 1;
    rci.pDependencies = &dep;
    VkRenderPass render_pass;
    CHECK(vkCreateRenderPass(device, &rci, NULL, &render_pass));
    VkFramebufferCreateInfo fci = {VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fci.renderPass = render_pass;
    fci.attachmentCount = 1;
    fci.pAttachments = &color_view;
    fci.width = fci.height = fci.layers = 1;
    VkFramebuffer framebuffer;
    CHECK(vkCreateFramebuffer(device, &fci, NULL, &framebuffer));

    VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                                 {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = shader_module("vert.spv");
    stages[0].pName = "main";
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = shader_module(opt_nocompare ? "frag_nc.spv" : "frag.spv");
    stages[1].pName = "main";
    VkPipelineVertexInputStateCreateInfo vi = {VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    VkPipelineInputAssemblyStateCreateInfo ia = {VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkViewport viewport = {0.0f, 0.0f, 1.0f, 1.0f, 0.0f, 1.0f};
    VkRect2D scissor = {{0, 0}, {1, 1}};
    VkPipelineViewportStateCreateInfo vp = {VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    vp.viewportCount = 1;
    vp.pViewports = &viewport;
    vp.scissorCount = 1;
    vp.pScissors = &scissor;
    VkPipelineRasterizationStateCreateInfo rs = {VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    rs.polygonMode = VK_POLYGON_MODE_FILL;
    rs.cullMode = VK_CULL_MODE_NONE;
    rs.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    rs.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo ms = {VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineColorBlendAttachmentState blend = {0};
    blend.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    VkPipelineColorBlendStateCreateInfo cb = {VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    cb.attachmentCount = 1;
    cb.pAttachments = &blend;
    VkGraphicsPipelineCreateInfo gci = {VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    gci.stageCount = 2;
    gci.pStages = stages;
    gci.pVertexInputState = &vi;
    gci.pInputAssemblyState = &ia;
    gci.pViewportState = &vp;
    gci.pRasterizationState = &rs;
    gci.pMultisampleState = &ms;
    gci.pColorBlendState = &cb;
    gci.layout = layout;
    gci.renderPass = render_pass;
    VkPipeline graphics;
    CHECK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &gci, NULL, &graphics));
    struct host_buffer readback = host_buffer(16, VK_BUFFER_USAGE_TRANSFER_DST_BIT);

    /* Upload both levels, all six layers, by vkCmdCopyBufferToImage (depth aspect); then
     * SHADER_READ_ONLY_OPTIMAL for the fragment and compute stages. Its own submission. */
    struct host_buffer staging = host_buffer(sizeof LEVEL0 + sizeof LEVEL1, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    memcpy(staging.ptr, LEVEL0, sizeof LEVEL0);
    memcpy((char *)staging.ptr + sizeof LEVEL0, LEVEL1, sizeof LEVEL1);
    VkBufferImageCopy regions[2] = {{0}, {0}};
    for (int l = 0; l < 2; l++) {
        regions[l].bufferOffset = l ? sizeof LEVEL0 : 0;
        regions[l].imageSubresource = (VkImageSubresourceLayers){VK_IMAGE_ASPECT_DEPTH_BIT, (uint32_t)l, 0, 6};
        regions[l].imageExtent = (VkExtent3D){2u >> l, 2u >> l, 1};
    }
    VkImageMemoryBarrier ib = {VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    ib.srcQueueFamilyIndex = ib.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    ib.image = image;
    ib.subresourceRange = vci.subresourceRange;
    ib.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    ib.newLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    ib.dstAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    VkCommandBuffer cmd = begin();
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, NULL, 0, NULL, 1, &ib);
    vkCmdCopyBufferToImage(cmd, staging.buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, (uint32_t)opt_levels, regions);
    ib.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    ib.newLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    ib.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    ib.dstAccessMask = VK_ACCESS_SHADER_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT | VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, NULL, 0, NULL, 1, &ib);
    submit(cmd);

    int compute_ok = 1, n_compute = 0, n_before = 0;
    float first = NAN, min_before = INFINITY, max_before = -INFINITY;
    /* Steps: 'c' a dispatch (its own submission), 'f' the draw (its own submission). */
    char steps[1100];
    int ns = 0;
    if (opt_frag_first) steps[ns++] = 'f';
    for (int i = 0; i < opt_runs; i++) steps[ns++] = 'c';
    if (!opt_frag_first) steps[ns++] = 'f', steps[ns++] = 'c';
    int drawn = 0;
    for (int k = 0; k < ns; k++) {
        float px[4];
        cmd = begin();
        if (steps[k] == 'c') {
            const float minus1[4] = {-1.0f, -1.0f, -1.0f, -1.0f};
            memcpy(out.ptr, minus1, sizeof minus1);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compute);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0, NULL);
            vkCmdPushConstants(cmd, layout, pc_stages, 0, sizeof P, P);
            vkCmdDispatch(cmd, 1, 1, 1);
            host_barrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT);
            submit(cmd);
            memcpy(px, out.ptr, sizeof px);
        } else {
            VkClearValue clear;
            clear.color.float32[0] = clear.color.float32[1] = clear.color.float32[2] = clear.color.float32[3] = -1.0f;
            VkRenderPassBeginInfo rbi = {VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
            rbi.renderPass = render_pass;
            rbi.framebuffer = framebuffer;
            rbi.renderArea.extent = (VkExtent2D){1, 1};
            rbi.clearValueCount = 1;
            rbi.pClearValues = &clear;
            vkCmdBeginRenderPass(cmd, &rbi, VK_SUBPASS_CONTENTS_INLINE);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, graphics);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 0, NULL);
            vkCmdPushConstants(cmd, layout, pc_stages, 0, sizeof P, P);
            vkCmdDraw(cmd, 3, 1, 0, 0);
            vkCmdEndRenderPass(cmd);
            VkBufferImageCopy back = {0};
            back.imageSubresource = (VkImageSubresourceLayers){VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
            back.imageExtent = (VkExtent3D){1, 1, 1};
            vkCmdCopyImageToBuffer(cmd, color, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback.buffer, 1, &back);
            host_barrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT);
            submit(cmd);
            memcpy(px, readback.ptr, sizeof px);
        }
        int ok = px[0] >= lo - tol && px[0] <= hi + tol;
        char label[64];
        if (steps[k] == 'c') {
            n_compute++;
            snprintf(label, sizeof label, "compute #%d%s", n_compute, drawn ? " (after the draw)" : "");
            if (n_compute == 1) first = px[0];
            if (!drawn) {
                n_before++;
                if (px[0] < min_before) min_before = px[0];
                if (px[0] > max_before) max_before = px[0];
            }
            compute_ok &= ok;
        } else {
            snprintf(label, sizeof label, "fragment");
            drawn = 1;
        }
        printf("%-28s %.9g  %s", label, px[0], ok ? "PASS" : "FAIL");
        if (opt_nocompare && !opt_corner && !opt_nearest)
            printf("  (column -1 texel as used: %.9g)", (px[0] - 0.6 * 0.9) / 0.4);
        printf("\n");
    }
    if (n_before > 1)
        printf("the %d dispatches before any draw: %s (min %.9g, max %.9g)\n", n_before,
               min_before == max_before ? "all identical" : "VARY", min_before, max_before);
    (void)first;
    vkDeviceWaitIdle(device);
    printf("validation messages: %d\n", n_messages);
    printf("verdict:   compute %s\n", compute_ok ? "PASS" : "FAIL");
    return compute_ok ? 0 : 1;
}
