//! The commands of one submission, in order: layout transitions and uploads, the render pass of
//! the draws, the read-backs, and the barrier that makes them visible to the host (Vulkan 1.3
//! §7.6 "Pipeline Barriers", §7.9 "Host Write Ordering Guarantees", §20 "Copy Commands").

use super::{full_range, Made, Renderer, TextureSpec};
use crate::compute::push_constants;
use crate::pipeline::color_range;
use crate::{Check, VkError};
use ash::vk;
use shadowcheck_model::Stage;
use shadowcheck_plan::layout::FB_SIZE;

/// The stages that read the textures: the fragment shader of the draws, the compute shader of
/// the compute-stage lookups.
const SHADERS: vk::PipelineStageFlags = vk::PipelineStageFlags::from_raw(
    vk::PipelineStageFlags::FRAGMENT_SHADER.as_raw()
        | vk::PipelineStageFlags::COMPUTE_SHADER.as_raw(),
);

impl Renderer {
    #[allow(clippy::too_many_arguments)]
    pub(super) fn record(
        &self,
        textures: &[TextureSpec],
        lookups: &[super::Lookup],
        made: &[Made],
        regions: &[Vec<vk::BufferImageCopy>],
        back: &[(usize, usize)],
        pipelines: &[Result<vk::Pipeline, String>],
    ) -> Result<(), VkError> {
        let d = &self.gpu.device;
        let cmd = self.cmd;
        let barrier = |t: &TextureSpec,
                       m: &Made,
                       from: vk::ImageLayout,
                       to: vk::ImageLayout,
                       src: vk::AccessFlags,
                       dst: vk::AccessFlags| {
            image_barrier(m.image, full_range(t), (from, src), (to, dst))
        };
        let all = |from, to, src, dst| -> Vec<vk::ImageMemoryBarrier> {
            textures
                .iter()
                .zip(made)
                .map(|(t, m)| barrier(t, m, from, to, src, dst))
                .collect()
        };
        let size = FB_SIZE as u32;
        // SAFETY: every handle is this device's and alive until the fence is waited for; the
        // command buffer is not in use (the previous submission's fence was waited for).
        unsafe {
            d.reset_command_buffer(cmd, vk::CommandBufferResetFlags::empty())
                .check("vkResetCommandBuffer")?;
            let bi = vk::CommandBufferBeginInfo::default()
                .flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT);
            d.begin_command_buffer(cmd, &bi)
                .check("vkBeginCommandBuffer")?;
            // Uploads: UNDEFINED -> TRANSFER_DST, copy, -> SHADER_READ_ONLY for the fragment
            // and compute shaders.
            d.cmd_pipeline_barrier(
                cmd,
                vk::PipelineStageFlags::TOP_OF_PIPE,
                vk::PipelineStageFlags::TRANSFER,
                vk::DependencyFlags::empty(),
                &[],
                &[],
                &all(
                    vk::ImageLayout::UNDEFINED,
                    vk::ImageLayout::TRANSFER_DST_OPTIMAL,
                    vk::AccessFlags::empty(),
                    vk::AccessFlags::TRANSFER_WRITE,
                ),
            );
            for (m, r) in made.iter().zip(regions) {
                d.cmd_copy_buffer_to_image(
                    cmd,
                    self.staging.buffer,
                    m.image,
                    vk::ImageLayout::TRANSFER_DST_OPTIMAL,
                    r,
                );
            }
            d.cmd_pipeline_barrier(
                cmd,
                vk::PipelineStageFlags::TRANSFER,
                SHADERS,
                vk::DependencyFlags::empty(),
                &[],
                &[],
                &all(
                    vk::ImageLayout::TRANSFER_DST_OPTIMAL,
                    vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
                    vk::AccessFlags::TRANSFER_WRITE,
                    vk::AccessFlags::SHADER_READ,
                ),
            );
            // The draws: the result image cleared to -1, which no lookup returns.
            let clear = [vk::ClearValue {
                color: vk::ClearColorValue { float32: [-1.0; 4] },
            }];
            let rbi = vk::RenderPassBeginInfo::default()
                .render_pass(self.target.render_pass)
                .framebuffer(self.target.framebuffer)
                .render_area(vk::Rect2D {
                    offset: vk::Offset2D { x: 0, y: 0 },
                    extent: vk::Extent2D {
                        width: size,
                        height: size,
                    },
                })
                .clear_values(&clear);
            d.cmd_begin_render_pass(cmd, &rbi, vk::SubpassContents::INLINE);
            d.cmd_bind_vertex_buffers(cmd, 0, &[self.vertices.buffer], &[0]);
            let mut bound: Option<vk::Pipeline> = None;
            let mut set: Option<vk::DescriptorSet> = None;
            for (k, (l, p)) in lookups.iter().zip(pipelines).enumerate() {
                let Ok(p) = p else { continue };
                if l.plan.key.stage == Stage::Compute {
                    continue;
                }
                let Some(m) = made.get(l.texture) else {
                    continue;
                };
                if bound != Some(*p) {
                    d.cmd_bind_pipeline(cmd, vk::PipelineBindPoint::GRAPHICS, *p);
                    // u_base: slot k is lookup k (the vertices carry k).
                    d.cmd_push_constants(
                        cmd,
                        self.programs.layout,
                        vk::ShaderStageFlags::VERTEX | vk::ShaderStageFlags::FRAGMENT,
                        0,
                        &0i32.to_ne_bytes(),
                    );
                    bound = Some(*p);
                }
                if set != Some(m.set) {
                    d.cmd_bind_descriptor_sets(
                        cmd,
                        vk::PipelineBindPoint::GRAPHICS,
                        self.programs.layout,
                        0,
                        &[m.set],
                        &[],
                    );
                    set = Some(m.set);
                }
                d.cmd_draw(cmd, 6, 1, 6 * k as u32, 0);
            }
            d.cmd_end_render_pass(cmd);
            self.record_dispatches(lookups, made, pipelines);
            // Read-backs: each texture's level base (depth aspect), then the result image (left
            // in TRANSFER_SRC_OPTIMAL by the render pass, or by the dispatches' barrier).
            d.cmd_pipeline_barrier(
                cmd,
                SHADERS,
                vk::PipelineStageFlags::TRANSFER,
                vk::DependencyFlags::empty(),
                &[],
                &[],
                &all(
                    vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
                    vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
                    vk::AccessFlags::empty(),
                    vk::AccessFlags::TRANSFER_READ,
                ),
            );
            for ((t, m), &(at, _)) in textures.iter().zip(made).zip(back) {
                let r = [super::copy_region(
                    at,
                    vk::ImageAspectFlags::DEPTH,
                    0,
                    &t.shape,
                )];
                d.cmd_copy_image_to_buffer(
                    cmd,
                    m.image,
                    vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
                    self.texels.buffer,
                    &r,
                );
            }
            let r = [vk::BufferImageCopy {
                buffer_offset: 0,
                buffer_row_length: 0,
                buffer_image_height: 0,
                image_subresource: vk::ImageSubresourceLayers {
                    aspect_mask: vk::ImageAspectFlags::COLOR,
                    mip_level: 0,
                    base_array_layer: 0,
                    layer_count: 1,
                },
                image_offset: vk::Offset3D { x: 0, y: 0, z: 0 },
                image_extent: vk::Extent3D {
                    width: size,
                    height: size,
                    depth: 1,
                },
            }];
            d.cmd_copy_image_to_buffer(
                cmd,
                self.target.image,
                vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
                self.target.readback.buffer,
                &r,
            );
            let host = [vk::MemoryBarrier::default()
                .src_access_mask(vk::AccessFlags::TRANSFER_WRITE)
                .dst_access_mask(vk::AccessFlags::HOST_READ)];
            d.cmd_pipeline_barrier(
                cmd,
                vk::PipelineStageFlags::TRANSFER,
                vk::PipelineStageFlags::HOST,
                vk::DependencyFlags::empty(),
                &host,
                &[],
                &[],
            );
            d.end_command_buffer(cmd).check("vkEndCommandBuffer")?;
        }
        Ok(())
    }

    /// The compute-stage lookups (`crate::compute`): the result image from the render pass's
    /// TRANSFER_SRC_OPTIMAL to GENERAL, after its clear and the draws' writes; one dispatch of one
    /// invocation per lookup, storing at its slot's pixel; back to TRANSFER_SRC_OPTIMAL for the
    /// read-back, after the stores. Nothing is recorded when the submission has none.
    fn record_dispatches(
        &self,
        lookups: &[super::Lookup],
        made: &[Made],
        pipelines: &[Result<vk::Pipeline, String>],
    ) {
        let d = &self.gpu.device;
        let cmd = self.cmd;
        let compute: Vec<(usize, &super::Lookup, vk::Pipeline)> = lookups
            .iter()
            .zip(pipelines)
            .enumerate()
            .filter_map(|(k, (l, p))| match p {
                Ok(p) if l.plan.key.stage == Stage::Compute => Some((k, l, *p)),
                _ => None,
            })
            .collect();
        if compute.is_empty() {
            return;
        }
        let image = self.target.image;
        let to_general = [image_barrier(
            image,
            color_range(),
            (
                vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
                vk::AccessFlags::COLOR_ATTACHMENT_WRITE,
            ),
            (vk::ImageLayout::GENERAL, vk::AccessFlags::SHADER_WRITE),
        )];
        let to_transfer = [image_barrier(
            image,
            color_range(),
            (vk::ImageLayout::GENERAL, vk::AccessFlags::SHADER_WRITE),
            (
                vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
                vk::AccessFlags::TRANSFER_READ,
            ),
        )];
        // SAFETY: as in `record`: every handle is alive until the fence is waited for, and the
        // command buffer is recording.
        unsafe {
            // TRANSFER too: the render pass's final layout transition happens before the TRANSFER
            // stage of its external dependency, and this barrier's scope chains after it.
            d.cmd_pipeline_barrier(
                cmd,
                vk::PipelineStageFlags::COLOR_ATTACHMENT_OUTPUT | vk::PipelineStageFlags::TRANSFER,
                vk::PipelineStageFlags::COMPUTE_SHADER,
                vk::DependencyFlags::empty(),
                &[],
                &[],
                &to_general,
            );
            let mut bound: Option<vk::Pipeline> = None;
            for (k, l, p) in compute {
                let Some(m) = made.get(l.texture) else {
                    continue;
                };
                if bound != Some(p) {
                    d.cmd_bind_pipeline(cmd, vk::PipelineBindPoint::COMPUTE, p);
                    bound = Some(p);
                }
                d.cmd_bind_descriptor_sets(
                    cmd,
                    vk::PipelineBindPoint::COMPUTE,
                    self.compute.layout,
                    0,
                    &[m.set],
                    &[],
                );
                d.cmd_push_constants(
                    cmd,
                    self.compute.layout,
                    vk::ShaderStageFlags::COMPUTE,
                    0,
                    &push_constants(l.plan, k),
                );
                d.cmd_dispatch(cmd, 1, 1, 1);
            }
            d.cmd_pipeline_barrier(
                cmd,
                vk::PipelineStageFlags::COMPUTE_SHADER,
                vk::PipelineStageFlags::TRANSFER,
                vk::DependencyFlags::empty(),
                &[],
                &[],
                &to_transfer,
            );
        }
    }
}

/// A layout transition of `range` of `image`, with the accesses it orders (§7.6.2 "Image Memory
/// Barriers"; no queue family transfer).
fn image_barrier(
    image: vk::Image,
    range: vk::ImageSubresourceRange,
    (from, src): (vk::ImageLayout, vk::AccessFlags),
    (to, dst): (vk::ImageLayout, vk::AccessFlags),
) -> vk::ImageMemoryBarrier<'static> {
    vk::ImageMemoryBarrier::default()
        .src_access_mask(src)
        .dst_access_mask(dst)
        .old_layout(from)
        .new_layout(to)
        .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
        .image(image)
        .subresource_range(range)
}
