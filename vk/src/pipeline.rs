//! The fixed objects of a worker: host-visible buffers, the result image (RGBA32F, one 2x2 quad
//! per slot, `shadowcheck_plan::layout`) with its render pass and framebuffer, and one graphics
//! pipeline per shader key (Vulkan 1.3 §10 "Pipelines"), compiled once and kept.

use crate::device::Gpu;
use crate::{spirv, Check, VkError};
use ash::vk;
use shadowcheck_plan::layout::FB_SIZE;
use shadowcheck_plan::shaders::vulkan::{self as glsl, PUSH_CONSTANT_BYTES};
use shadowcheck_plan::shaders::{PARAM_ATTRIBS, PARAM_FLOATS};
use shadowcheck_plan::ShaderKey;
use std::collections::HashMap;

/// The result image's format: RGBA32F, every lookup result exact ("Required Format Support": COLOR_ATTACHMENT is
/// required for it).
pub const RESULT_FORMAT: vk::Format = vk::Format::R32G32B32A32_SFLOAT;

/// A buffer in host-visible, host-coherent memory, mapped for its life.
pub struct HostBuffer {
    pub buffer: vk::Buffer,
    memory: vk::DeviceMemory,
    pub size: u64,
    ptr: *mut u8,
}

impl HostBuffer {
    pub fn new(gpu: &Gpu, size: u64, usage: vk::BufferUsageFlags) -> Result<HostBuffer, VkError> {
        let d = &gpu.device;
        let size = size.max(16);
        let ci = vk::BufferCreateInfo::default()
            .size(size)
            .usage(usage)
            .sharing_mode(vk::SharingMode::EXCLUSIVE);
        // SAFETY: valid device and create info.
        let buffer = unsafe { d.create_buffer(&ci, None) }.check("vkCreateBuffer")?;
        // SAFETY: `buffer` was created from `d`.
        let req = unsafe { d.get_buffer_memory_requirements(buffer) };
        let host = vk::MemoryPropertyFlags::HOST_VISIBLE | vk::MemoryPropertyFlags::HOST_COHERENT;
        let Some(ty) = gpu.memory_type(req.memory_type_bits, host, host) else {
            // SAFETY: unused buffer of this device.
            unsafe { d.destroy_buffer(buffer, None) };
            return Err(VkError::Setup("no host-visible coherent memory".into()));
        };
        let ai = vk::MemoryAllocateInfo::default()
            .allocation_size(req.size)
            .memory_type_index(ty);
        // SAFETY: valid allocate info; the memory is bound and mapped below, freed in `destroy`.
        let made = unsafe {
            d.allocate_memory(&ai, None)
                .check("vkAllocateMemory")
                .and_then(|m| {
                    d.bind_buffer_memory(buffer, m, 0)
                        .and_then(|_| {
                            d.map_memory(m, 0, vk::WHOLE_SIZE, vk::MemoryMapFlags::empty())
                        })
                        .map(|p| (m, p as *mut u8))
                        .map_err(|r| {
                            d.free_memory(m, None);
                            VkError::call("vkMapMemory", r)
                        })
                })
        };
        match made {
            Ok((memory, ptr)) => Ok(HostBuffer {
                buffer,
                memory,
                size,
                ptr,
            }),
            Err(e) => {
                // SAFETY: unused buffer of this device.
                unsafe { d.destroy_buffer(buffer, None) };
                Err(e)
            }
        }
    }

    /// Copies `bytes` to `offset` (the caller keeps within `size`).
    pub fn write(&mut self, offset: u64, bytes: &[u8]) {
        let end = offset.saturating_add(bytes.len() as u64);
        if end <= self.size {
            // SAFETY: the mapping covers `size` bytes and the range is inside it; no queue
            // access to the buffer is in flight while the worker writes (it waits for its fence).
            unsafe {
                std::ptr::copy_nonoverlapping(
                    bytes.as_ptr(),
                    self.ptr.add(offset as usize),
                    bytes.len(),
                )
            };
        }
    }

    /// `len` bytes at `offset` (empty outside the buffer).
    pub fn read(&self, offset: u64, len: usize) -> &[u8] {
        if offset.saturating_add(len as u64) > self.size {
            return &[];
        }
        // SAFETY: inside the mapping; the queue's writes finished (fence waited) and were made
        // visible to the host (a barrier to HOST_READ, §7.9 "Host Write Ordering Guarantees").
        unsafe { std::slice::from_raw_parts(self.ptr.add(offset as usize), len) }
    }

    pub fn destroy(&mut self, gpu: &Gpu) {
        // SAFETY: the device is idle with respect to this buffer (the worker waited its fence).
        unsafe {
            gpu.device.destroy_buffer(self.buffer, None);
            gpu.device.free_memory(self.memory, None);
        }
        self.buffer = vk::Buffer::null();
    }
}

/// Device-local memory bound to an image.
pub fn bind_image_memory(gpu: &Gpu, image: vk::Image) -> Result<vk::DeviceMemory, VkError> {
    let d = &gpu.device;
    // SAFETY: `image` was created from `d`.
    let req = unsafe { d.get_image_memory_requirements(image) };
    let ty = gpu
        .memory_type(
            req.memory_type_bits,
            vk::MemoryPropertyFlags::empty(),
            vk::MemoryPropertyFlags::DEVICE_LOCAL,
        )
        .ok_or_else(|| VkError::Setup("no memory type for an image".into()))?;
    let ai = vk::MemoryAllocateInfo::default()
        .allocation_size(req.size)
        .memory_type_index(ty);
    // SAFETY: valid allocate info; bound once here.
    unsafe {
        let m = d.allocate_memory(&ai, None).check("vkAllocateMemory")?;
        if let Err(r) = d.bind_image_memory(image, m, 0) {
            d.free_memory(m, None);
            return Err(VkError::call("vkBindImageMemory", r));
        }
        Ok(m)
    }
}

/// The result image, its render pass and framebuffer, and the buffer it is read back into.
pub struct ResultTarget {
    pub image: vk::Image,
    memory: vk::DeviceMemory,
    pub view: vk::ImageView,
    pub render_pass: vk::RenderPass,
    pub framebuffer: vk::Framebuffer,
    pub readback: HostBuffer,
}

impl ResultTarget {
    pub fn new(gpu: &Gpu) -> Result<ResultTarget, VkError> {
        let d = &gpu.device;
        let size = FB_SIZE as u32;
        let ci = vk::ImageCreateInfo::default()
            .image_type(vk::ImageType::TYPE_2D)
            .format(RESULT_FORMAT)
            .extent(vk::Extent3D {
                width: size,
                height: size,
                depth: 1,
            })
            .mip_levels(1)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .tiling(vk::ImageTiling::OPTIMAL)
            // STORAGE: the compute-stage lookups store into it (`compute.rs`); RGBA32F has
            // STORAGE_IMAGE in "Required Format Support".
            .usage(
                vk::ImageUsageFlags::COLOR_ATTACHMENT
                    | vk::ImageUsageFlags::TRANSFER_SRC
                    | vk::ImageUsageFlags::STORAGE,
            )
            .initial_layout(vk::ImageLayout::UNDEFINED);
        // SAFETY: valid create infos; every object is destroyed in `destroy`.
        unsafe {
            let image = d.create_image(&ci, None).check("vkCreateImage")?;
            let memory = bind_image_memory(gpu, image)?;
            let vci = vk::ImageViewCreateInfo::default()
                .image(image)
                .view_type(vk::ImageViewType::TYPE_2D)
                .format(RESULT_FORMAT)
                .subresource_range(color_range());
            let view = d.create_image_view(&vci, None).check("vkCreateImageView")?;
            // Cleared to -1 (no path returns it); left in TRANSFER_SRC_OPTIMAL for the copy, the
            // copy made to wait for the attachment writes (§8.1 "Render Pass Creation").
            let att = [vk::AttachmentDescription::default()
                .format(RESULT_FORMAT)
                .samples(vk::SampleCountFlags::TYPE_1)
                .load_op(vk::AttachmentLoadOp::CLEAR)
                .store_op(vk::AttachmentStoreOp::STORE)
                .stencil_load_op(vk::AttachmentLoadOp::DONT_CARE)
                .stencil_store_op(vk::AttachmentStoreOp::DONT_CARE)
                .initial_layout(vk::ImageLayout::UNDEFINED)
                .final_layout(vk::ImageLayout::TRANSFER_SRC_OPTIMAL)];
            let refs = [vk::AttachmentReference::default()
                .attachment(0)
                .layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)];
            let sub = [vk::SubpassDescription::default()
                .pipeline_bind_point(vk::PipelineBindPoint::GRAPHICS)
                .color_attachments(&refs)];
            let deps = [vk::SubpassDependency::default()
                .src_subpass(0)
                .dst_subpass(vk::SUBPASS_EXTERNAL)
                .src_stage_mask(vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT)
                .src_access_mask(vk::AccessFlags::COLOR_ATTACHMENT_WRITE)
                .dst_stage_mask(vk::PipelineStageFlags::TRANSFER)
                .dst_access_mask(vk::AccessFlags::TRANSFER_READ)];
            let rci = vk::RenderPassCreateInfo::default()
                .attachments(&att)
                .subpasses(&sub)
                .dependencies(&deps);
            let render_pass = d
                .create_render_pass(&rci, None)
                .check("vkCreateRenderPass")?;
            let views = [view];
            let fci = vk::FramebufferCreateInfo::default()
                .render_pass(render_pass)
                .attachments(&views)
                .width(size)
                .height(size)
                .layers(1);
            let framebuffer = d
                .create_framebuffer(&fci, None)
                .check("vkCreateFramebuffer")?;
            let readback = HostBuffer::new(
                gpu,
                (size * size * 16) as u64,
                vk::BufferUsageFlags::TRANSFER_DST,
            )?;
            Ok(ResultTarget {
                image,
                memory,
                view,
                render_pass,
                framebuffer,
                readback,
            })
        }
    }

    pub fn destroy(&mut self, gpu: &Gpu) {
        let d = &gpu.device;
        // SAFETY: the device is idle (the worker waits before dropping).
        unsafe {
            d.destroy_framebuffer(self.framebuffer, None);
            d.destroy_render_pass(self.render_pass, None);
            d.destroy_image_view(self.view, None);
            d.destroy_image(self.image, None);
            d.free_memory(self.memory, None);
        }
        self.readback.destroy(gpu);
    }
}

pub fn color_range() -> vk::ImageSubresourceRange {
    vk::ImageSubresourceRange {
        aspect_mask: vk::ImageAspectFlags::COLOR,
        base_mip_level: 0,
        level_count: 1,
        base_array_layer: 0,
        layer_count: 1,
    }
}

/// The descriptor set layout (the combined image sampler at binding 0, read by the fragment or
/// compute shader; the result image as a storage image at binding 1, written by the compute
/// shader of a compute-stage lookup, `compute.rs`), the graphics pipeline layout (that set and
/// the push constant `u_base`) and a graphics pipeline per shader key.
pub struct Programs {
    pub set_layout: vk::DescriptorSetLayout,
    pub layout: vk::PipelineLayout,
    pipelines: HashMap<ShaderKey, Result<vk::Pipeline, String>>,
}

impl Programs {
    pub fn new(gpu: &Gpu) -> Result<Programs, VkError> {
        let d = &gpu.device;
        let bindings = [
            vk::DescriptorSetLayoutBinding::default()
                .binding(0)
                .descriptor_type(vk::DescriptorType::COMBINED_IMAGE_SAMPLER)
                .descriptor_count(1)
                .stage_flags(vk::ShaderStageFlags::FRAGMENT | vk::ShaderStageFlags::COMPUTE),
            vk::DescriptorSetLayoutBinding::default()
                .binding(1)
                .descriptor_type(vk::DescriptorType::STORAGE_IMAGE)
                .descriptor_count(1)
                .stage_flags(vk::ShaderStageFlags::COMPUTE),
        ];
        let sci = vk::DescriptorSetLayoutCreateInfo::default().bindings(&bindings);
        // SAFETY: valid create infos; destroyed in `destroy`.
        unsafe {
            let set_layout = d
                .create_descriptor_set_layout(&sci, None)
                .check("vkCreateDescriptorSetLayout")?;
            let sets = [set_layout];
            let pc = [vk::PushConstantRange::default()
                .stage_flags(vk::ShaderStageFlags::VERTEX | vk::ShaderStageFlags::FRAGMENT)
                .offset(0)
                .size(PUSH_CONSTANT_BYTES)];
            let lci = vk::PipelineLayoutCreateInfo::default()
                .set_layouts(&sets)
                .push_constant_ranges(&pc);
            let layout = d
                .create_pipeline_layout(&lci, None)
                .check("vkCreatePipelineLayout")?;
            Ok(Programs {
                set_layout,
                layout,
                pipelines: HashMap::new(),
            })
        }
    }

    /// Pipelines made so far.
    pub fn count(&self) -> usize {
        self.pipelines.len()
    }

    /// The pipeline of `key`, made on first use; a key whose program does not compile answers
    /// the same error every time.
    pub fn get(
        &mut self,
        gpu: &Gpu,
        render_pass: vk::RenderPass,
        key: &ShaderKey,
    ) -> Result<vk::Pipeline, String> {
        if let Some(p) = self.pipelines.get(key) {
            return p.clone();
        }
        let made = self.make(gpu, render_pass, key).map_err(|e| e.to_string());
        self.pipelines.insert(*key, made.clone());
        made
    }

    fn make(
        &self,
        gpu: &Gpu,
        render_pass: vk::RenderPass,
        key: &ShaderKey,
    ) -> Result<vk::Pipeline, VkError> {
        let d = &gpu.device;
        let (vs, fs) = glsl::glsl(key, FB_SIZE);
        let words = [spirv::compile(&vs, "vert")?, spirv::compile(&fs, "frag")?];
        let mut modules = vec![];
        for w in &words {
            let ci = vk::ShaderModuleCreateInfo::default().code(w);
            // SAFETY: valid SPIR-V words from the compiler.
            match unsafe { d.create_shader_module(&ci, None) } {
                Ok(m) => modules.push(m),
                Err(r) => {
                    destroy_modules(gpu, &modules);
                    return Err(VkError::call("vkCreateShaderModule", r));
                }
            }
        }
        let made = self.pipeline(gpu, render_pass, modules[0], modules[1]);
        destroy_modules(gpu, &modules);
        made
    }

    fn pipeline(
        &self,
        gpu: &Gpu,
        render_pass: vk::RenderPass,
        vs: vk::ShaderModule,
        fs: vk::ShaderModule,
    ) -> Result<vk::Pipeline, VkError> {
        let stages = [
            vk::PipelineShaderStageCreateInfo::default()
                .stage(vk::ShaderStageFlags::VERTEX)
                .module(vs)
                .name(c"main"),
            vk::PipelineShaderStageCreateInfo::default()
                .stage(vk::ShaderStageFlags::FRAGMENT)
                .module(fs)
                .name(c"main"),
        ];
        // Six vertices per case, PARAM_FLOATS floats each, at PARAM_ATTRIBS' locations.
        let binding = [vk::VertexInputBindingDescription::default()
            .binding(0)
            .stride((PARAM_FLOATS * 4) as u32)
            .input_rate(vk::VertexInputRate::VERTEX)];
        let attrs: Vec<vk::VertexInputAttributeDescription> = PARAM_ATTRIBS
            .iter()
            .map(|&(loc, _, size, at)| {
                vk::VertexInputAttributeDescription::default()
                    .location(loc)
                    .binding(0)
                    .format(match size {
                        1 => vk::Format::R32_SFLOAT,
                        2 => vk::Format::R32G32_SFLOAT,
                        3 => vk::Format::R32G32B32_SFLOAT,
                        _ => vk::Format::R32G32B32A32_SFLOAT,
                    })
                    .offset((at * 4) as u32)
            })
            .collect();
        let vi = vk::PipelineVertexInputStateCreateInfo::default()
            .vertex_binding_descriptions(&binding)
            .vertex_attribute_descriptions(&attrs);
        let ia = vk::PipelineInputAssemblyStateCreateInfo::default()
            .topology(vk::PrimitiveTopology::TRIANGLE_LIST);
        let size = FB_SIZE as u32;
        let viewports = [vk::Viewport {
            x: 0.0,
            y: 0.0,
            width: size as f32,
            height: size as f32,
            min_depth: 0.0,
            max_depth: 1.0,
        }];
        let scissors = [vk::Rect2D {
            offset: vk::Offset2D { x: 0, y: 0 },
            extent: vk::Extent2D {
                width: size,
                height: size,
            },
        }];
        let vp = vk::PipelineViewportStateCreateInfo::default()
            .viewports(&viewports)
            .scissors(&scissors);
        let rs = vk::PipelineRasterizationStateCreateInfo::default()
            .polygon_mode(vk::PolygonMode::FILL)
            .cull_mode(vk::CullModeFlags::NONE)
            .front_face(vk::FrontFace::COUNTER_CLOCKWISE)
            .line_width(1.0);
        let ms = vk::PipelineMultisampleStateCreateInfo::default()
            .rasterization_samples(vk::SampleCountFlags::TYPE_1);
        let blend = [vk::PipelineColorBlendAttachmentState::default()
            .blend_enable(false)
            .color_write_mask(vk::ColorComponentFlags::RGBA)];
        let cb = vk::PipelineColorBlendStateCreateInfo::default().attachments(&blend);
        let ci = [vk::GraphicsPipelineCreateInfo::default()
            .stages(&stages)
            .vertex_input_state(&vi)
            .input_assembly_state(&ia)
            .viewport_state(&vp)
            .rasterization_state(&rs)
            .multisample_state(&ms)
            .color_blend_state(&cb)
            .layout(self.layout)
            .render_pass(render_pass)
            .subpass(0)];
        // SAFETY: valid create info; the pipeline is destroyed in `destroy`.
        let made = unsafe {
            gpu.device
                .create_graphics_pipelines(vk::PipelineCache::null(), &ci, None)
        };
        match made {
            Ok(p) => p
                .into_iter()
                .next()
                .ok_or_else(|| VkError::Setup("no pipeline made".into())),
            Err((_, r)) => Err(VkError::call("vkCreateGraphicsPipelines", r)),
        }
    }

    pub fn destroy(&mut self, gpu: &Gpu) {
        // SAFETY: the device is idle (the worker waits before dropping).
        unsafe {
            for p in self.pipelines.values().flatten() {
                gpu.device.destroy_pipeline(*p, None);
            }
            gpu.device.destroy_pipeline_layout(self.layout, None);
            gpu.device
                .destroy_descriptor_set_layout(self.set_layout, None);
        }
        self.pipelines.clear();
    }
}

fn destroy_modules(gpu: &Gpu, modules: &[vk::ShaderModule]) {
    for m in modules {
        // SAFETY: a module of this device, used by no pending pipeline creation.
        unsafe { gpu.device.destroy_shader_module(*m, None) };
    }
}
