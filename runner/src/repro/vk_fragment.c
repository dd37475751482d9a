
/* ---- The fragment stage: slot 0's quad drawn in a render pass (vk/src/pipeline.rs, vk/src/draw/record.rs). ---- */

/* The colour target: a FB x FB RGBA32F image (every result exact), its render pass (cleared to -1,
 * which no lookup returns; left in TRANSFER_SRC_OPTIMAL for the copy, "Render Pass Creation") and
 * framebuffer, as vk/src/pipeline.rs makes them. */
static VkImage color;
static VkRenderPass render_pass;
static VkFramebuffer framebuffer;

static void make_target(void) {
    VkImageView view;
    make_rgba32f(VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, &color, &view);
    VkAttachmentDescription att = {0};
    att.format = VK_FORMAT_R32G32B32A32_SFLOAT;
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
    CHECK(vkCreateRenderPass(device, &rci, NULL, &render_pass));
    VkFramebufferCreateInfo fci = {VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    fci.renderPass = render_pass;
    fci.attachmentCount = 1;
    fci.pAttachments = &view;
    fci.width = FB;
    fci.height = FB;
    fci.layers = 1;
    CHECK(vkCreateFramebuffer(device, &fci, NULL, &framebuffer));
}

/* One combined image sampler at set 0, binding 0 (fragment stage), the push constant u_base
 * (both stages), and the pipeline of vert.spv / frag.spv (vk/src/pipeline.rs, "Pipelines"). */
static VkDescriptorSetLayout set_layout;
static VkPipelineLayout layout;
static VkPipeline pipeline;

static void make_pipeline(void) {
    VkDescriptorSetLayoutBinding binding = {0};
    binding.binding = 0;
    binding.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    binding.descriptorCount = 1;
    binding.stageFlags = VK_SHADER_STAGE_FRAGMENT_BIT;
    VkDescriptorSetLayoutCreateInfo sci = {VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
    sci.bindingCount = 1;
    sci.pBindings = &binding;
    CHECK(vkCreateDescriptorSetLayout(device, &sci, NULL, &set_layout));
    VkPushConstantRange pc = {VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof(int32_t)};
    VkPipelineLayoutCreateInfo lci = {VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
    lci.setLayoutCount = 1;
    lci.pSetLayouts = &set_layout;
    lci.pushConstantRangeCount = 1;
    lci.pPushConstantRanges = &pc;
    CHECK(vkCreatePipelineLayout(device, &lci, NULL, &layout));

    VkPipelineShaderStageCreateInfo stages[2] = {{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO},
                                                 {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO}};
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = shader_module("vert.spv");
    stages[0].pName = "main";
    stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
    stages[1].module = shader_module("frag.spv");
    stages[1].pName = "main";
    VkVertexInputBindingDescription vb = {0, PARAM_FLOATS * sizeof(float), VK_VERTEX_INPUT_RATE_VERTEX};
    VkVertexInputAttributeDescription attrs[sizeof ATTRIBS / sizeof ATTRIBS[0]];
    for (unsigned i = 0; i < sizeof ATTRIBS / sizeof ATTRIBS[0]; i++) {
        attrs[i].location = ATTRIBS[i].location;
        attrs[i].binding = 0;
        attrs[i].format = ATTRIBS[i].format;
        attrs[i].offset = ATTRIBS[i].offset_floats * sizeof(float);
    }
    VkPipelineVertexInputStateCreateInfo vi = {VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    vi.vertexBindingDescriptionCount = 1;
    vi.pVertexBindingDescriptions = &vb;
    vi.vertexAttributeDescriptionCount = sizeof ATTRIBS / sizeof ATTRIBS[0];
    vi.pVertexAttributeDescriptions = attrs;
    VkPipelineInputAssemblyStateCreateInfo ia = {VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ia.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
    VkViewport viewport = {0.0f, 0.0f, (float)FB, (float)FB, 0.0f, 1.0f};
    VkRect2D scissor = {{0, 0}, {FB, FB}};
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
    VkGraphicsPipelineCreateInfo ci = {VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO};
    ci.stageCount = 2;
    ci.pStages = stages;
    ci.pVertexInputState = &vi;
    ci.pInputAssemblyState = &ia;
    ci.pViewportState = &vp;
    ci.pRasterizationState = &rs;
    ci.pMultisampleState = &ms;
    ci.pColorBlendState = &cb;
    ci.layout = layout;
    ci.renderPass = render_pass;
    ci.subpass = 0;
    CHECK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &ci, NULL, &pipeline));
}

int main(void) {
    make_device();
    make_target();
    make_pipeline();
    make_texture();
    VkDescriptorSet set = make_set(set_layout, VK_NULL_HANDLE);
    stage_texels();
    struct host_buffer vertices = host_buffer(sizeof VERTICES, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    memcpy(vertices.ptr, VERTICES, sizeof VERTICES);
    struct host_buffer readback = host_buffer(FB * FB * 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT);

    /* The commands (vk/src/draw/record.rs; "Pipeline Barriers", "Copy Commands"). */
    VkCommandBuffer cmd = begin_commands();
    record_upload(cmd, VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT);
    VkClearValue clear;
    clear.color.float32[0] = clear.color.float32[1] = clear.color.float32[2] = clear.color.float32[3] = -1.0f;
    VkRenderPassBeginInfo rbi = {VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    rbi.renderPass = render_pass;
    rbi.framebuffer = framebuffer;
    rbi.renderArea.extent.width = FB;
    rbi.renderArea.extent.height = FB;
    rbi.clearValueCount = 1;
    rbi.pClearValues = &clear;
    vkCmdBeginRenderPass(cmd, &rbi, VK_SUBPASS_CONTENTS_INLINE);
    VkDeviceSize zero = 0;
    vkCmdBindVertexBuffers(cmd, 0, 1, &vertices.buffer, &zero);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline);
    const int32_t u_base = 0; /* slot 0: the vertices carry k = 0 */
    vkCmdPushConstants(cmd, layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0, sizeof u_base, &u_base);
    vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout, 0, 1, &set, 0, NULL);
    vkCmdDraw(cmd, 6, 1, 0, 0);
    vkCmdEndRenderPass(cmd);
    record_read_back(cmd, color, readback.buffer);
    submit_and_wait(cmd);

    /* Slot 0's result: pixel (0, 0), the first texel of the rows read back (the worker's
     * layout::pixel(0)). */
    float px[4];
    memcpy(px, readback.ptr, sizeof px);
    return judge(px);
}
