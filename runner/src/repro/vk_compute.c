
/* ---- The compute stage: one dispatch of comp.spv storing into the result image (vk/src/compute.rs,
 * vk/src/draw/record.rs `record_dispatches`). ---- */

/* The result image: a FB x FB RGBA32F image (every result exact) with STORAGE usage, and its 2D
 * view for the storage-image descriptor, as vk/src/pipeline.rs makes it. TRANSFER_DST for the
 * clear (vkCmdClearColorImage); TRANSFER_SRC for the read-back. */
static VkImage result;
static VkImageView result_view;

static void make_result(void) {
    VkFormatProperties fp;
    vkGetPhysicalDeviceFormatProperties(physical, VK_FORMAT_R32G32B32A32_SFLOAT, &fp);
    if (!(fp.optimalTilingFeatures & VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT)) lacks("STORAGE_IMAGE on VK_FORMAT_R32G32B32A32_SFLOAT");
    make_rgba32f(VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, &result, &result_view);
}

/* The worker's descriptor set layout (vk/src/pipeline.rs `Programs::new`): binding 0 the combined
 * image sampler u_tex, binding 1 the result image as the storage image u_out; the push constants
 * of PUSH (compute stage, 32 bytes); the compute pipeline of comp.spv (vk/src/compute.rs,
 * "Compute Pipelines"). */
static VkDescriptorSetLayout set_layout;
static VkPipelineLayout layout;
static VkPipeline pipeline;

static void make_pipeline(void) {
    VkDescriptorSetLayoutBinding bindings[2] = {{0}, {0}};
    bindings[0].binding = 0;
    bindings[0].descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    bindings[0].descriptorCount = 1;
    bindings[0].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    bindings[1].binding = 1;
    bindings[1].descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    bindings[1].descriptorCount = 1;
    bindings[1].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
    VkDescriptorSetLayoutCreateInfo sci = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    sci.bindingCount = 2;
    sci.pBindings = bindings;
    CHECK(vkCreateDescriptorSetLayout(device, &sci, NULL, &set_layout));
    VkPushConstantRange pc = {VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof PUSH};
    VkPipelineLayoutCreateInfo lci = {VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    lci.setLayoutCount = 1;
    lci.pSetLayouts = &set_layout;
    lci.pushConstantRangeCount = 1;
    lci.pPushConstantRanges = &pc;
    CHECK(vkCreatePipelineLayout(device, &lci, NULL, &layout));
    VkComputePipelineCreateInfo ci = {VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    ci.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    ci.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    ci.stage.module = shader_module("comp.spv");
    ci.stage.pName = "main";
    ci.layout = layout;
    CHECK(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &ci, NULL, &pipeline));
}

int main(void) {
    make_device();
    make_result();
    make_pipeline();
    make_texture();
    VkDescriptorSet set = make_set(set_layout, result_view);
    stage_texels();
    struct host_buffer readback = host_buffer(FB * FB * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT);

    /* The commands (vk/src/draw/record.rs; "Pipeline Barriers", "Clear Commands", "Dispatching
     * Commands", "Copy Commands"). */
    VkCommandBuffer cmd = begin_commands();
    record_upload(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT);
    /* The result image cleared to -1, which no lookup returns. The worker clears it in the render
     * pass of its fragment-stage draws (loadOp CLEAR, final layout TRANSFER_SRC_OPTIMAL), then
     * moves it to GENERAL for the dispatches. Here vkCmdClearColorImage does the same: it writes
     * -1 to every texel of the result image (and to nothing else), and the barrier after it makes
     * those writes visible to the compute shader in the GENERAL layout, as the worker's barrier
     * does for the render pass's clear. The dispatch sees the same image contents either way. No
     * draw is recorded before the dispatch: on SwiftShader a dispatch that follows a draw sampling
     * the same image gives a different (correct) result (reports/vulkan/repro/compute-cube-edge),
     * and the harness's observation is that of a dispatch with no such draw before it. */
    VkImageMemoryBarrier b = image_barrier(result, VK_IMAGE_ASPECT_COLOR_BIT, VK_IMAGE_LAYOUT_UNDEFINED,
                                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0, VK_ACCESS_TRANSFER_WRITE_BIT);
    b.subresourceRange.levelCount = 1;
    b.subresourceRange.layerCount = 1;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, NULL, 0, NULL, 1, &b);
    VkClearColorValue clear;
    clear.float32[0] = clear.float32[1] = clear.float32[2] = clear.float32[3] = -1.0f;
    vkCmdClearColorImage(cmd, result, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &clear, 1, &b.subresourceRange);
    b.oldLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
    b.newLayout = VK_IMAGE_LAYOUT_GENERAL;
    b.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, 0, 0, NULL, 0, NULL, 1, &b);
    /* The dispatch of slot 0's lookup: one invocation, storing at PUSH.u_at. */
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout, 0, 1, &set, 0, NULL);
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_COMPUTE_BIT, 0, sizeof PUSH, &PUSH);
    vkCmdDispatch(cmd, 1, 1, 1);
    /* GENERAL -> TRANSFER_SRC_OPTIMAL for the read-back, after the store. */
    b.oldLayout = VK_IMAGE_LAYOUT_GENERAL;
    b.newLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    b.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    b.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 0, NULL, 0, NULL, 1, &b);
    record_read_back(cmd, result, readback.buffer);
    submit_and_wait(cmd);

    /* Slot 0's result: the pixel its invocation stored at, PUSH.u_at = (0, 0) (the worker's
     * layout::pixel(0)), in the rows read back. */
    float px[4];
    memcpy(px, (const char *)readback.ptr + ((size_t)PUSH.u_at[1] * FB + (size_t)PUSH.u_at[0]) * 16, sizeof px);
    return judge(px);
}
