//! One submission: the images of a group of textures uploaded (vkCmdCopyBufferToImage), every
//! lookup drawn as its slot's 2x2 quad (`vkCmdDraw(6, 1, 6k, 0)`, one descriptor set per texture),
//! the result image and each texture's level base copied back (vkCmdCopyImageToBuffer), then one
//! fence waited for (Vulkan 1.3 §7 "Synchronization and Cache Control").

use crate::compute::ComputePrograms;
use crate::device::{FormatInfo, Gpu};
use crate::pipeline::{bind_image_memory, HostBuffer, Programs, ResultTarget};
use crate::sampler::SamplerState;
use crate::texture::{self, Shape};
use crate::{Check, VkError};
use ash::vk;
use shadowcheck_model::{Case, Stage, Texels};
use shadowcheck_plan::layout::{pixel, CASE_VERTICES, CORNERS, FB_SIZE};
use shadowcheck_plan::shaders::PARAM_FLOATS;
use shadowcheck_plan::Plan;

/// Most textures one submission creates (each an image, a memory allocation, a view, a sampler
/// and a descriptor set: well inside maxMemoryAllocationCount's 4096 and
/// maxSamplerAllocationCount's 4000).
pub const MAX_TEXTURES: usize = 256;

/// How long one submission may take before the worker gives the device up.
const FENCE_TIMEOUT_NS: u64 = 120_000_000_000;

/// A texture of a submission: its case, sampler and view state, image shape and format.
pub struct TextureSpec<'a> {
    pub case: &'a Case,
    pub state: SamplerState,
    pub shape: Shape,
    pub format: FormatInfo,
}

/// A lookup of a submission: the texture it samples (an index) and its plan.
pub struct Lookup<'a> {
    pub texture: usize,
    pub plan: &'a Plan,
}

/// The Vulkan objects of one texture, destroyed after the submission.
#[derive(Default)]
struct Made {
    image: vk::Image,
    memory: vk::DeviceMemory,
    view: vk::ImageView,
    sampler: vk::Sampler,
    set: vk::DescriptorSet,
}

/// The device and the objects every submission uses.
pub struct Renderer {
    target: ResultTarget,
    programs: Programs,
    compute: ComputePrograms,
    pool: vk::CommandPool,
    cmd: vk::CommandBuffer,
    fence: vk::Fence,
    descriptors: vk::DescriptorPool,
    vertices: HostBuffer,
    staging: HostBuffer,
    texels: HostBuffer,
    /// Lookups drawn so far.
    pub drawn: usize,
    pub gpu: Gpu,
}

fn align(n: usize) -> usize {
    n.div_ceil(16) * 16
}

impl Renderer {
    pub fn new(gpu: Gpu) -> Result<Renderer, VkError> {
        let d = &gpu.device;
        let target = ResultTarget::new(&gpu)?;
        let programs = Programs::new(&gpu)?;
        let compute = ComputePrograms::new(&gpu, programs.set_layout)?;
        // SAFETY: valid create infos; every object is destroyed in Drop.
        let (pool, cmd, fence, descriptors) = unsafe {
            let pci = vk::CommandPoolCreateInfo::default()
                .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER)
                .queue_family_index(gpu.queue_family);
            let pool = d
                .create_command_pool(&pci, None)
                .check("vkCreateCommandPool")?;
            let ai = vk::CommandBufferAllocateInfo::default()
                .command_pool(pool)
                .level(vk::CommandBufferLevel::PRIMARY)
                .command_buffer_count(1);
            let cmd = d
                .allocate_command_buffers(&ai)
                .check("vkAllocateCommandBuffers")?
                .first()
                .copied()
                .ok_or_else(|| VkError::Setup("no command buffer".into()))?;
            let fence = d
                .create_fence(&vk::FenceCreateInfo::default(), None)
                .check("vkCreateFence")?;
            let sizes = [
                vk::DescriptorPoolSize {
                    ty: vk::DescriptorType::COMBINED_IMAGE_SAMPLER,
                    descriptor_count: MAX_TEXTURES as u32,
                },
                vk::DescriptorPoolSize {
                    ty: vk::DescriptorType::STORAGE_IMAGE,
                    descriptor_count: MAX_TEXTURES as u32,
                },
            ];
            let dci = vk::DescriptorPoolCreateInfo::default()
                .max_sets(MAX_TEXTURES as u32)
                .pool_sizes(&sizes);
            let descriptors = d
                .create_descriptor_pool(&dci, None)
                .check("vkCreateDescriptorPool")?;
            (pool, cmd, fence, descriptors)
        };
        let vertices = HostBuffer::new(&gpu, 1 << 20, vk::BufferUsageFlags::VERTEX_BUFFER)?;
        let staging = HostBuffer::new(&gpu, 1 << 20, vk::BufferUsageFlags::TRANSFER_SRC)?;
        let texels = HostBuffer::new(&gpu, 1 << 20, vk::BufferUsageFlags::TRANSFER_DST)?;
        Ok(Renderer {
            target,
            programs,
            compute,
            pool,
            cmd,
            fence,
            descriptors,
            vertices,
            staging,
            texels,
            drawn: 0,
            gpu,
        })
    }

    /// Pipelines compiled so far (graphics and compute).
    pub fn pipelines(&self) -> usize {
        self.programs.count() + self.compute.count()
    }

    /// `buf` with room for `len` bytes (replaced by a larger one when it has not).
    fn room(
        gpu: &Gpu,
        buf: &mut HostBuffer,
        len: usize,
        usage: vk::BufferUsageFlags,
    ) -> Result<(), VkError> {
        if (len as u64) > buf.size {
            let bigger = HostBuffer::new(gpu, (len as u64).next_power_of_two(), usage)?;
            let mut old = std::mem::replace(buf, bigger);
            old.destroy(gpu);
        }
        Ok(())
    }

    /// Draws `lookups` (slot k: lookup k, at most `layout::CAPACITY`) on `textures` (at most
    /// [`MAX_TEXTURES`]): each lookup's RGBA or why it has none (its program does not compile),
    /// and each texture's level base as stored. An `Err` is the submission's (every lookup of it
    /// fails); [`VkError::DeviceLost`] means the device is gone.
    #[allow(clippy::type_complexity)]
    pub fn draw(
        &mut self,
        textures: &[TextureSpec],
        lookups: &[Lookup],
    ) -> Result<(Vec<Result<[f32; 4], String>>, Vec<Texels>), VkError> {
        let mut made: Vec<Made> = Vec::with_capacity(textures.len());
        let result = self.draw_with(textures, lookups, &mut made);
        let d = &self.gpu.device;
        // SAFETY: the submission finished or never started (the fence was waited for, or the
        // device is lost, when nothing of it runs any more): the objects are unused.
        unsafe {
            if matches!(result, Err(VkError::DeviceLost(_))) {
                let _ = d.device_wait_idle();
            }
            for m in made {
                d.destroy_sampler(m.sampler, None);
                d.destroy_image_view(m.view, None);
                d.destroy_image(m.image, None);
                d.free_memory(m.memory, None);
            }
            let _ =
                d.reset_descriptor_pool(self.descriptors, vk::DescriptorPoolResetFlags::empty());
        }
        result
    }

    #[allow(clippy::type_complexity)]
    fn draw_with(
        &mut self,
        textures: &[TextureSpec],
        lookups: &[Lookup],
        made: &mut Vec<Made>,
    ) -> Result<(Vec<Result<[f32; 4], String>>, Vec<Texels>), VkError> {
        // The bytes: every texture's levels (depth, then stencil), 16-byte aligned ("Copying Data
        // Between Buffers and Images": a depth/stencil copy's bufferOffset is a multiple of 4).
        let mut upload: Vec<u8> = Vec::new();
        let mut regions: Vec<Vec<vk::BufferImageCopy>> = Vec::with_capacity(textures.len());
        let mut back: Vec<(usize, usize)> = Vec::with_capacity(textures.len());
        let mut back_len = 0usize;
        for t in textures {
            let mut r = vec![];
            for (i, level) in t.case.texture.levels.iter().enumerate() {
                let mut aspects = vec![(
                    vk::ImageAspectFlags::DEPTH,
                    texture::depth_bytes(t.format.format, level).map_err(VkError::Setup)?,
                )];
                if t.format.format.has_stencil() {
                    aspects.push((vk::ImageAspectFlags::STENCIL, texture::stencil_bytes(level)));
                }
                for (aspect, bytes) in aspects {
                    let at = align(upload.len());
                    upload.resize(at, 0);
                    upload.extend_from_slice(&bytes);
                    r.push(copy_region(at, aspect, i as u32, &t.shape));
                }
            }
            regions.push(r);
            let n = t.case.texture.levels[0].texel_count()
                * texture::depth_texel_bytes(t.format.format);
            back.push((back_len, n));
            back_len = align(back_len + n);
        }
        let g = &self.gpu;
        Self::room(
            g,
            &mut self.staging,
            upload.len(),
            vk::BufferUsageFlags::TRANSFER_SRC,
        )?;
        Self::room(
            g,
            &mut self.texels,
            back_len,
            vk::BufferUsageFlags::TRANSFER_DST,
        )?;
        self.staging.write(0, &upload);
        // Six vertices per lookup: corner, (x, k, unit 0), P, dx, dy (`shadowcheck_plan::layout`).
        let mut verts: Vec<f32> = Vec::with_capacity(lookups.len() * CASE_VERTICES * PARAM_FLOATS);
        for (k, l) in lookups.iter().enumerate() {
            let p = l.plan;
            for corner in CORNERS {
                verts.extend_from_slice(&corner);
                verts.extend_from_slice(&[p.x, k as f32, 0.0]);
                verts.extend_from_slice(&p.p);
                verts.extend_from_slice(&p.dx);
                verts.extend_from_slice(&p.dy);
            }
        }
        let vbytes: Vec<u8> = verts.iter().flat_map(|f| f.to_ne_bytes()).collect();
        Self::room(
            g,
            &mut self.vertices,
            vbytes.len(),
            vk::BufferUsageFlags::VERTEX_BUFFER,
        )?;
        self.vertices.write(0, &vbytes);
        for t in textures {
            made.push(Made::default());
            let m = made
                .last_mut()
                .ok_or_else(|| VkError::Setup("internal".into()))?;
            self.make_texture(t, m)?;
        }
        let pipelines: Vec<Result<vk::Pipeline, String>> = lookups
            .iter()
            .map(|l| {
                if l.plan.key.stage == Stage::Compute {
                    self.compute.get(&self.gpu, &l.plan.key)
                } else {
                    self.programs
                        .get(&self.gpu, self.target.render_pass, &l.plan.key)
                }
            })
            .collect();
        self.record(textures, lookups, made, &regions, &back, &pipelines)?;
        self.submit()?;
        self.drawn += lookups.len();
        let rgba = pipelines
            .into_iter()
            .enumerate()
            .map(|(k, p)| {
                p.map(|_| {
                    let (x, y) = pixel(k);
                    let at = ((y * FB_SIZE + x) * 16) as u64;
                    let b = self.target.readback.read(at, 16);
                    let f = |i: usize| {
                        b.get(i..i + 4)
                            .map_or(f32::NAN, |c| f32::from_ne_bytes([c[0], c[1], c[2], c[3]]))
                    };
                    [f(0), f(4), f(8), f(12)]
                })
            })
            .collect();
        let stored = textures
            .iter()
            .zip(&back)
            .map(|(t, &(at, n))| texture::decode(t.format.format, self.texels.read(at as u64, n)))
            .collect();
        Ok((rgba, stored))
    }

    /// The image, memory, view, sampler and descriptor set of `t`.
    fn make_texture(&self, t: &TextureSpec, m: &mut Made) -> Result<(), VkError> {
        let d = &self.gpu.device;
        let s = &t.state;
        let ici = vk::ImageCreateInfo::default()
            .flags(t.shape.flags)
            .image_type(t.shape.image_type)
            .format(t.format.vk)
            .extent(t.shape.extent)
            .mip_levels(t.shape.levels)
            .array_layers(t.shape.layers)
            .samples(vk::SampleCountFlags::TYPE_1)
            .tiling(vk::ImageTiling::OPTIMAL)
            .usage(
                vk::ImageUsageFlags::SAMPLED
                    | vk::ImageUsageFlags::TRANSFER_DST
                    | vk::ImageUsageFlags::TRANSFER_SRC,
            )
            .initial_layout(vk::ImageLayout::UNDEFINED);
        // SAFETY: valid create infos (the worker checked formats, features and limits); each
        // object is recorded in `m` as soon as it exists, for `draw` to destroy.
        unsafe {
            m.image = d.create_image(&ici, None).check("vkCreateImage")?;
            m.memory = bind_image_memory(&self.gpu, m.image)?;
            let vci = vk::ImageViewCreateInfo::default()
                .image(m.image)
                .view_type(t.shape.view_type)
                .format(t.format.vk)
                .subresource_range(vk::ImageSubresourceRange {
                    aspect_mask: s.aspect,
                    base_mip_level: 0,
                    level_count: s.view_levels,
                    base_array_layer: 0,
                    layer_count: t.shape.layers,
                });
            m.view = d.create_image_view(&vci, None).check("vkCreateImageView")?;
            let mut custom = vk::SamplerCustomBorderColorCreateInfoEXT::default()
                .format(t.format.vk)
                .custom_border_color(vk::ClearColorValue {
                    float32: s.custom_border.unwrap_or_default(),
                });
            let mut sci = vk::SamplerCreateInfo::default()
                .mag_filter(s.mag)
                .min_filter(s.min)
                .mipmap_mode(s.mipmap)
                .address_mode_u(s.address[0])
                .address_mode_v(s.address[1])
                .address_mode_w(s.address[2])
                .mip_lod_bias(s.lod_bias)
                .compare_enable(s.compare.is_some())
                .compare_op(s.compare.unwrap_or(vk::CompareOp::NEVER))
                .min_lod(s.min_lod)
                .max_lod(s.max_lod)
                .border_color(s.border);
            if s.custom_border.is_some() {
                sci = sci.push_next(&mut custom);
            }
            m.sampler = d.create_sampler(&sci, None).check("vkCreateSampler")?;
            let layouts = [self.programs.set_layout];
            let ai = vk::DescriptorSetAllocateInfo::default()
                .descriptor_pool(self.descriptors)
                .set_layouts(&layouts);
            m.set = d
                .allocate_descriptor_sets(&ai)
                .check("vkAllocateDescriptorSets")?
                .first()
                .copied()
                .ok_or_else(|| VkError::Setup("no descriptor set".into()))?;
            let info = [vk::DescriptorImageInfo {
                sampler: m.sampler,
                image_view: m.view,
                image_layout: vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
            }];
            // The result image for a compute-stage lookup's store (`compute.rs`).
            let result = [vk::DescriptorImageInfo {
                sampler: vk::Sampler::null(),
                image_view: self.target.view,
                image_layout: vk::ImageLayout::GENERAL,
            }];
            let write = [
                vk::WriteDescriptorSet::default()
                    .dst_set(m.set)
                    .dst_binding(0)
                    .descriptor_type(vk::DescriptorType::COMBINED_IMAGE_SAMPLER)
                    .image_info(&info),
                vk::WriteDescriptorSet::default()
                    .dst_set(m.set)
                    .dst_binding(1)
                    .descriptor_type(vk::DescriptorType::STORAGE_IMAGE)
                    .image_info(&result),
            ];
            d.update_descriptor_sets(&write, &[]);
        }
        Ok(())
    }

    fn submit(&mut self) -> Result<(), VkError> {
        let d = &self.gpu.device;
        let cmds = [self.cmd];
        let submit = [vk::SubmitInfo::default().command_buffers(&cmds)];
        // SAFETY: the command buffer is recorded; the fence is unsignalled (reset after each
        // wait).
        unsafe {
            d.queue_submit(self.gpu.queue, &submit, self.fence)
                .check("vkQueueSubmit")?;
            let waited = d.wait_for_fences(&[self.fence], true, FENCE_TIMEOUT_NS);
            match waited {
                Ok(()) => d.reset_fences(&[self.fence]).check("vkResetFences"),
                Err(vk::Result::TIMEOUT) => Err(VkError::DeviceLost(format!(
                    "the submission did not finish within {} s",
                    FENCE_TIMEOUT_NS / 1_000_000_000
                ))),
                Err(r) => Err(VkError::call("vkWaitForFences", r)),
            }
        }
    }
}

/// The copy of one aspect of level `level`, all layers, from `offset` (tightly packed: x, then
/// y, then layer, as the model's texels are).
fn copy_region(
    offset: usize,
    aspect: vk::ImageAspectFlags,
    level: u32,
    shape: &Shape,
) -> vk::BufferImageCopy {
    let e = shape.extent;
    vk::BufferImageCopy {
        buffer_offset: offset as u64,
        buffer_row_length: 0,
        buffer_image_height: 0,
        image_subresource: vk::ImageSubresourceLayers {
            aspect_mask: aspect,
            mip_level: level,
            base_array_layer: 0,
            layer_count: shape.layers,
        },
        image_offset: vk::Offset3D { x: 0, y: 0, z: 0 },
        image_extent: vk::Extent3D {
            width: (e.width >> level).max(1),
            height: (e.height >> level).max(1),
            depth: 1,
        },
    }
}

mod record;

impl Drop for Renderer {
    fn drop(&mut self) {
        let g = &self.gpu;
        // SAFETY: waiting for idle first: nothing of these objects is in use.
        unsafe {
            let _ = g.device.device_wait_idle();
            g.device.destroy_descriptor_pool(self.descriptors, None);
            g.device.destroy_fence(self.fence, None);
            g.device.destroy_command_pool(self.pool, None);
        }
        self.vertices.destroy(g);
        self.staging.destroy(g);
        self.texels.destroy(g);
        self.programs.destroy(g);
        self.compute.destroy(g);
        self.target.destroy(g);
    }
}

/// The whole-image range of `t`'s aspects.
fn full_range(t: &TextureSpec) -> vk::ImageSubresourceRange {
    vk::ImageSubresourceRange {
        aspect_mask: texture::aspects(&t.format),
        base_mip_level: 0,
        level_count: t.shape.levels,
        base_array_layer: 0,
        layer_count: t.shape.layers,
    }
}
