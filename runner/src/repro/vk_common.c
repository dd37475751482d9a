/* ---- The fixed part: what shadowcheck's Vulkan worker (vk/src/) does with the constants above. ---- */

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

/* The device cannot run this test: shadowcheck's worker answers it Skip there. */
static void lacks(const char *what) {
    fprintf(stderr, "setup failed: the device lacks %s (shadowcheck answers this test Skip on it)\n", what);
    exit(2);
}

static VkInstance instance;
static VkPhysicalDevice physical;
static VkDevice device;
static VkQueue queue;
static uint32_t family;
static VkPhysicalDeviceMemoryProperties memory;

/* "Device Memory Properties": a type of `bits` with `flags`, one with `prefer` too if any. */
static uint32_t memory_type(uint32_t bits, VkMemoryPropertyFlags flags, VkMemoryPropertyFlags prefer) {
    for (int pass = 0; pass < 2; pass++) {
        VkMemoryPropertyFlags want = pass == 0 ? flags | prefer : flags;
        for (uint32_t i = 0; i < memory.memoryTypeCount; i++)
            if ((bits & (1u << i)) && (memory.memoryTypes[i].propertyFlags & want) == want) return i;
    }
    die("no suitable memory type");
    return 0;
}

static VkDeviceMemory allocate(VkMemoryRequirements req, VkMemoryPropertyFlags flags, VkMemoryPropertyFlags prefer) {
    VkMemoryAllocateInfo ai = {VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    ai.allocationSize = req.size;
    ai.memoryTypeIndex = memory_type(req.memoryTypeBits, flags, prefer);
    VkDeviceMemory m;
    CHECK(vkAllocateMemory(device, &ai, NULL, &m));
    return m;
}

/* A buffer in host-visible, host-coherent memory, mapped. */
struct host_buffer {
    VkBuffer buffer;
    void *ptr;
};

static struct host_buffer host_buffer(VkDeviceSize size, VkBufferUsageFlags usage) {
    struct host_buffer b;
    VkBufferCreateInfo ci = {VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
    ci.size = size < 16 ? 16 : size;
    ci.usage = usage;
    ci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    CHECK(vkCreateBuffer(device, &ci, NULL, &b.buffer));
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(device, b.buffer, &req);
    const VkMemoryPropertyFlags host = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    VkDeviceMemory m = allocate(req, host, host);
    CHECK(vkBindBufferMemory(device, b.buffer, m, 0));
    CHECK(vkMapMemory(device, m, 0, VK_WHOLE_SIZE, 0, &b.ptr));
    return b;
}

static void bind_image(VkImage image) {
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device, image, &req);
    CHECK(vkBindImageMemory(device, image, allocate(req, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT), 0));
}

/* The result image of both stages: FB x FB RGBA32F (every result exact), with `usage`, in device
 * memory, and its 2D colour view, as vk/src/pipeline.rs makes it. */
static void make_rgba32f(VkImageUsageFlags usage, VkImage *image, VkImageView *view) {
    VkImageCreateInfo ci = {VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    ci.imageType = VK_IMAGE_TYPE_2D;
    ci.format = VK_FORMAT_R32G32B32A32_SFLOAT;
    ci.extent.width = FB;
    ci.extent.height = FB;
    ci.extent.depth = 1;
    ci.mipLevels = 1;
    ci.arrayLayers = 1;
    ci.samples = VK_SAMPLE_COUNT_1_BIT;
    ci.tiling = VK_IMAGE_TILING_OPTIMAL;
    ci.usage = usage;
    CHECK(vkCreateImage(device, &ci, NULL, image));
    bind_image(*image);
    VkImageViewCreateInfo vci = {VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = *image;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = ci.format;
    vci.subresourceRange.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
    vci.subresourceRange.levelCount = 1;
    vci.subresourceRange.layerCount = 1;
    CHECK(vkCreateImageView(device, &vci, NULL, view));
}

/* The rank of a device type (the worker's, for vk:native): a real GPU first, a CPU last. With
 * VK_ICD_FILENAMES naming one driver there is one device. */
static int rank(VkPhysicalDeviceType t) {
    switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 4;
    default: return 3;
    }
}

static int has_extension(const VkExtensionProperties *e, uint32_t n, const char *name) {
    for (uint32_t i = 0; i < n; i++)
        if (strcmp(e[i].extensionName, name) == 0) return 1;
    return 0;
}

/* Instance, physical device and device as the worker makes them (vk/src/device/): API version
 * min(loader, 1.3); the features the worker enables where the device has them ("Features":
 * imageCubeArray, shaderImageGatherExtended, samplerMirrorClampToEdge, customBorderColors). */
static void make_device(void) {
    uint32_t loader = VK_API_VERSION_1_0;
    CHECK(vkEnumerateInstanceVersion(&loader));
    if (loader < VK_API_VERSION_1_1) die("the Vulkan loader is older than 1.1");
    VkApplicationInfo app = {VK_STRUCTURE_TYPE_APPLICATION_INFO};
    app.pApplicationName = "shadowcheck";
    app.apiVersion = loader < VK_API_VERSION_1_3 ? loader : VK_API_VERSION_1_3;
    VkInstanceCreateInfo ici = {VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
    ici.pApplicationInfo = &app;
    CHECK(vkCreateInstance(&ici, NULL, &instance));

    VkPhysicalDevice all[16];
    uint32_t n = 16;
    VkResult r = vkEnumeratePhysicalDevices(instance, &n, all);
    if (r != VK_SUCCESS && r != VK_INCOMPLETE) check_vk(r, "vkEnumeratePhysicalDevices");
    if (n == 0) die("no Vulkan physical device (is VK_ICD_FILENAMES right?)");
    VkPhysicalDeviceProperties props;
    int best = 99;
    for (uint32_t i = 0; i < n; i++) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(all[i], &p);
        if (rank(p.deviceType) < best) {
            best = rank(p.deviceType);
            physical = all[i];
            props = p;
        }
    }
    uint32_t api = props.apiVersion;
    printf("VK_DEVICE: %s\nVK_API_VERSION: %u.%u.%u\n", props.deviceName, VK_API_VERSION_MAJOR(api),
           VK_API_VERSION_MINOR(api), VK_API_VERSION_PATCH(api));
    if (api >= VK_API_VERSION_1_2) {
        /* VkPhysicalDeviceDriverProperties ("Devices"), Vulkan 1.2. */
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

    VkQueueFamilyProperties families[16];
    uint32_t nf = 16;
    vkGetPhysicalDeviceQueueFamilyProperties(physical, &nf, families);
    family = nf;
    for (uint32_t i = 0; i < nf && family == nf; i++)
        if (families[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) family = i;
    if (family == nf) die("no graphics queue");

    uint32_t ne = 0;
    CHECK(vkEnumerateDeviceExtensionProperties(physical, NULL, &ne, NULL));
    VkExtensionProperties *exts = calloc(ne ? ne : 1, sizeof *exts);
    if (!exts) die("out of memory");
    CHECK(vkEnumerateDeviceExtensionProperties(physical, NULL, &ne, exts));
    int custom_ext = has_extension(exts, ne, VK_EXT_CUSTOM_BORDER_COLOR_EXTENSION_NAME);
    int mirror_ext = has_extension(exts, ne, VK_KHR_SAMPLER_MIRROR_CLAMP_TO_EDGE_EXTENSION_NAME);
    free(exts);

    /* What the device has ("Feature Queries"). */
    VkPhysicalDeviceVulkan12Features v12 = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    VkPhysicalDeviceCustomBorderColorFeaturesEXT cbc = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_CUSTOM_BORDER_COLOR_FEATURES_EXT};
    VkPhysicalDeviceFeatures2 f2 = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    void **next = &f2.pNext;
    if (api >= VK_API_VERSION_1_2) {
        *next = &v12;
        next = &v12.pNext;
    }
    if (custom_ext) *next = &cbc;
    vkGetPhysicalDeviceFeatures2(physical, &f2);
    int mirror = (api >= VK_API_VERSION_1_2 && v12.samplerMirrorClampToEdge) || (api < VK_API_VERSION_1_2 && mirror_ext);
    int custom = custom_ext && cbc.customBorderColors;

    /* What this test needs ("Format Feature Flags", "Limits"), as the worker's capabilities and
     * vk/src/sampler.rs decide; a device without it gets a Skip from the harness. */
    if (NEED_IMAGE_CUBE_ARRAY && !f2.features.imageCubeArray) lacks("imageCubeArray");
    if (NEED_MIRROR_CLAMP_TO_EDGE && !mirror) lacks("samplerMirrorClampToEdge");
    if (NEED_CUSTOM_BORDER_COLOR && !custom) lacks("VK_EXT_custom_border_color");
    if (fabsf(SAMPLER.mipLodBias) > props.limits.maxSamplerLodBias) lacks("a maxSamplerLodBias this large");
    if (NEED_GATHER_EXTENDED && !f2.features.shaderImageGatherExtended) lacks("shaderImageGatherExtended (textureGatherOffsets)");
    const int32_t min_offset = IS_GATHER ? props.limits.minTexelGatherOffset : props.limits.minTexelOffset;
    const uint32_t max_offset = IS_GATHER ? props.limits.maxTexelGatherOffset : props.limits.maxTexelOffset;
    for (unsigned k = 0; k < sizeof TEXEL_OFFSETS / sizeof TEXEL_OFFSETS[0]; k++)
        for (int i = 0; i < 2; i++)
            if (TEXEL_OFFSETS[k][i] < min_offset || (TEXEL_OFFSETS[k][i] > 0 && (uint32_t)TEXEL_OFFSETS[k][i] > max_offset))
                lacks(IS_GATHER ? "this gather offset within minTexelGatherOffset..maxTexelGatherOffset"
                                : "this texel offset within minTexelOffset..maxTexelOffset");
    VkFormatProperties fp;
    vkGetPhysicalDeviceFormatProperties(physical, IMAGE.format, &fp);
    VkFormatFeatureFlags f = fp.optimalTilingFeatures;
    const VkFormatFeatureFlags usable = VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT | VK_FORMAT_FEATURE_TRANSFER_DST_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT;
    if ((f & usable) != usable) lacks("SAMPLED_IMAGE, TRANSFER_DST and TRANSFER_SRC on " FORMAT_NAME);
    if (NEED_FILTER_LINEAR && !(f & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
        lacks("SAMPLED_IMAGE_FILTER_LINEAR on " FORMAT_NAME " (LINEAR without comparison)");
    if (NEED_DEPTH_COMPARISON && api >= VK_API_VERSION_1_3) {
        VkFormatProperties3 p3 = {VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_3};
        VkFormatProperties2 p2 = {VK_STRUCTURE_TYPE_FORMAT_PROPERTIES_2};
        p2.pNext = &p3;
        vkGetPhysicalDeviceFormatProperties2(physical, IMAGE.format, &p2);
        if (!(p3.optimalTilingFeatures & VK_FORMAT_FEATURE_2_SAMPLED_IMAGE_DEPTH_COMPARISON_BIT))
            lacks("SAMPLED_IMAGE_DEPTH_COMPARISON on " FORMAT_NAME);
    }

    /* What the worker enables: only what it may use. */
    VkPhysicalDeviceVulkan12Features en12 = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES};
    en12.samplerMirrorClampToEdge = api >= VK_API_VERSION_1_2 && v12.samplerMirrorClampToEdge;
    VkPhysicalDeviceCustomBorderColorFeaturesEXT en_cbc = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_CUSTOM_BORDER_COLOR_FEATURES_EXT};
    en_cbc.customBorderColors = custom ? VK_TRUE : VK_FALSE;
    VkPhysicalDeviceFeatures2 en = {VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2};
    en.features.imageCubeArray = f2.features.imageCubeArray;
    en.features.shaderImageGatherExtended = f2.features.shaderImageGatherExtended;
    const char *names[2];
    uint32_t nn = 0;
    next = &en.pNext;
    if (api >= VK_API_VERSION_1_2) {
        *next = &en12;
        next = &en12.pNext;
    } else if (mirror_ext) {
        names[nn++] = VK_KHR_SAMPLER_MIRROR_CLAMP_TO_EDGE_EXTENSION_NAME;
    }
    if (custom) {
        names[nn++] = VK_EXT_CUSTOM_BORDER_COLOR_EXTENSION_NAME;
        *next = &en_cbc;
    }
    const float priority = 1.0f;
    VkDeviceQueueCreateInfo qci = {VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
    qci.queueFamilyIndex = family;
    qci.queueCount = 1;
    qci.pQueuePriorities = &priority;
    VkDeviceCreateInfo dci = {VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO};
    dci.pNext = &en;
    dci.queueCreateInfoCount = 1;
    dci.pQueueCreateInfos = &qci;
    dci.enabledExtensionCount = nn;
    dci.ppEnabledExtensionNames = names;
    CHECK(vkCreateDevice(physical, &dci, NULL, &device));
    vkGetDeviceQueue(device, family, 0, &queue);
}

/* The SPIR-V that build.sh compiled from the .glsl beside this program ("Shader Modules"). */
static VkShaderModule shader_module(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "setup failed: cannot read %s (run the program from its directory: sh build.sh)\n", path);
        exit(2);
    }
    static uint32_t words[1 << 18];
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

static VkImageMemoryBarrier image_barrier(VkImage image, VkImageAspectFlags aspects, VkImageLayout from, VkImageLayout to,
                                          VkAccessFlags src, VkAccessFlags dst) {
    VkImageMemoryBarrier b = {VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
    b.srcAccessMask = src;
    b.dstAccessMask = dst;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image;
    b.subresourceRange.aspectMask = aspects;
    b.subresourceRange.levelCount = IMAGE.mipLevels;
    b.subresourceRange.layerCount = IMAGE.arrayLayers;
    return b;
}


/* The depth image, its view and sampler (vk/src/draw.rs, "Images", "Image Views", "Samplers"). */
static VkImage image;
static VkImageView view;
static VkSampler sampler;

static void make_texture(void) {
    CHECK(vkCreateImage(device, &IMAGE, NULL, &image));
    bind_image(image);
    VkImageViewCreateInfo vci = VIEW;
    vci.image = image;
    CHECK(vkCreateImageView(device, &vci, NULL, &view));
    VkSamplerCreateInfo sci = SAMPLER;
#if NEED_CUSTOM_BORDER_COLOR
    VkSamplerCustomBorderColorCreateInfoEXT custom = {VK_STRUCTURE_TYPE_SAMPLER_CUSTOM_BORDER_COLOR_CREATE_INFO_EXT};
    memcpy(custom.customBorderColor.float32, CUSTOM_BORDER_COLOR, sizeof CUSTOM_BORDER_COLOR);
    custom.format = IMAGE.format;
    sci.pNext = &custom;
#endif
    CHECK(vkCreateSampler(device, &sci, NULL, &sampler));
}

/* The descriptor set of `set_layout_of`: the sampler and view at binding 0 and, where `storage` is a
 * view, the result image as a storage image at binding 1 (in the GENERAL layout, "Descriptor
 * Types": a storage image is accessed in GENERAL). */
static VkDescriptorSet make_set(VkDescriptorSetLayout set_layout_of, VkImageView storage) {
    VkDescriptorPoolSize sizes[2] = {{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1}, {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}};
    VkDescriptorPoolCreateInfo pci = {VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pci.maxSets = 1;
    pci.poolSizeCount = storage != VK_NULL_HANDLE ? 2 : 1;
    pci.pPoolSizes = sizes;
    VkDescriptorPool pool;
    CHECK(vkCreateDescriptorPool(device, &pci, NULL, &pool));
    VkDescriptorSetAllocateInfo dai = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
    dai.descriptorPool = pool;
    dai.descriptorSetCount = 1;
    dai.pSetLayouts = &set_layout_of;
    VkDescriptorSet set;
    CHECK(vkAllocateDescriptorSets(device, &dai, &set));
    VkDescriptorImageInfo info[2] = {{sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
                                     {VK_NULL_HANDLE, storage, VK_IMAGE_LAYOUT_GENERAL}};
    VkWriteDescriptorSet writes[2] = {{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}, {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET}};
    for (uint32_t i = 0; i < 2; i++) {
        writes[i].dstSet = set;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = sizes[i].type;
        writes[i].pImageInfo = &info[i];
    }
    vkUpdateDescriptorSets(device, storage != VK_NULL_HANDLE ? 2 : 1, writes, 0, NULL);
    return set;
}

/* The texel bytes, each aspect of each level 16-byte aligned ("Copying Data Between Buffers
 * and Images": a depth/stencil copy's bufferOffset is a multiple of 4), all layers at once. */
enum { N_UPLOADS = sizeof UPLOADS / sizeof UPLOADS[0] };
static struct host_buffer staging;
static VkBufferImageCopy regions[N_UPLOADS];

static void stage_texels(void) {
    VkDeviceSize total = 0;
    for (unsigned i = 0; i < N_UPLOADS; i++) total = (total + 15) / 16 * 16 + UPLOADS[i].size;
    staging = host_buffer(total, VK_BUFFER_USAGE_TRANSFER_SRC_BIT);
    VkDeviceSize at = 0;
    for (unsigned i = 0; i < N_UPLOADS; i++) {
        at = (at + 15) / 16 * 16;
        memcpy((char *)staging.ptr + at, UPLOADS[i].data, UPLOADS[i].size);
        VkBufferImageCopy r = {0};
        r.bufferOffset = at;
        r.imageSubresource.aspectMask = UPLOADS[i].aspect;
        r.imageSubresource.mipLevel = UPLOADS[i].level;
        r.imageSubresource.layerCount = IMAGE.arrayLayers;
        r.imageExtent.width = UPLOADS[i].width;
        r.imageExtent.height = UPLOADS[i].height;
        r.imageExtent.depth = 1;
        regions[i] = r;
        at += UPLOADS[i].size;
    }
}

/* One primary command buffer, recording (vk/src/draw/record.rs). */
static VkCommandBuffer begin_commands(void) {
    VkCommandPoolCreateInfo cpi = {VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    cpi.queueFamilyIndex = family;
    VkCommandPool cmd_pool;
    CHECK(vkCreateCommandPool(device, &cpi, NULL, &cmd_pool));
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

/* The upload ("Pipeline Barriers", "Copy Commands"): UNDEFINED -> TRANSFER_DST_OPTIMAL, the copy,
 * -> SHADER_READ_ONLY_OPTIMAL for the shader stage `readers` that samples the image. */
static void record_upload(VkCommandBuffer cmd, VkPipelineStageFlags readers) {
    VkImageMemoryBarrier b = image_barrier(image, IMAGE_ASPECTS, VK_IMAGE_LAYOUT_UNDEFINED,
                                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, NULL, 0, NULL, 1, &b);
    vkCmdCopyBufferToImage(cmd, staging.buffer, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, N_UPLOADS, regions);
    b = image_barrier(image, IMAGE_ASPECTS, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                      VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT);
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, readers, 0, 0, NULL, 0, NULL, 1, &b);
}

/* The read-back of the FB x FB result image (in TRANSFER_SRC_OPTIMAL) into `buffer`, made visible
 * to the host. */
static void record_read_back(VkCommandBuffer cmd, VkImage result, VkBuffer buffer) {
    VkBufferImageCopy back = {0};
    back.imageSubresource.aspectMask = VK_IMAGE_ASPECT_COLOR_BIT;
    back.imageSubresource.layerCount = 1;
    back.imageExtent.width = FB;
    back.imageExtent.height = FB;
    back.imageExtent.depth = 1;
    vkCmdCopyImageToBuffer(cmd, result, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer, 1, &back);
    VkMemoryBarrier host = {VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    host.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    host.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &host, 0, NULL, 0, NULL);
}

/* Ends the command buffer, submits it and waits for it. */
static void submit_and_wait(VkCommandBuffer cmd) {
    CHECK(vkEndCommandBuffer(cmd));
    VkFenceCreateInfo fci = {VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    CHECK(vkCreateFence(device, &fci, NULL, &fence));
    VkSubmitInfo submit = {VK_STRUCTURE_TYPE_SUBMIT_INFO};
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &cmd;
    CHECK(vkQueueSubmit(queue, 1, &submit, fence));
    CHECK(vkWaitForFences(device, 1, &fence, VK_TRUE, 120000000000ull));
}
