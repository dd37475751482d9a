//! Compute-stage lookups (`lookup.stage` `compute`): one compute pipeline per shader key
//! (`shadowcheck_plan::shaders::vulkan::compute_glsl`), and the commands that run them. Each
//! lookup is one dispatch of one invocation that stores its result with `imageStore` at its slot's
//! pixel of the result image, bound as a storage image (set 0, binding 1); its values are push
//! constants. The dispatches run after the render pass of the fragment-stage lookups, with the
//! result image in the GENERAL layout (Vulkan 1.3, "Descriptor Types", Storage Image: "Load and
//! store operations on storage images can only be done on images in VK_IMAGE_LAYOUT_GENERAL"
//! or the shared-present layout), and before the read-backs (§7.6 "Pipeline Barriers").

use crate::device::Gpu;
use crate::{spirv, Check, VkError};
use ash::vk;
use shadowcheck_plan::layout::pixel;
use shadowcheck_plan::shaders::vulkan::{compute_glsl, COMPUTE_PUSH_BYTES};
use shadowcheck_plan::{Plan, ShaderKey};
use std::collections::HashMap;

/// The pipeline layout of the compute pipelines (the worker's descriptor set layout, the push
/// constants of [`COMPUTE_PUSH_BYTES`]) and a pipeline per shader key.
pub struct ComputePrograms {
    pub layout: vk::PipelineLayout,
    pipelines: HashMap<ShaderKey, Result<vk::Pipeline, String>>,
}

impl ComputePrograms {
    pub fn new(gpu: &Gpu, set_layout: vk::DescriptorSetLayout) -> Result<Self, VkError> {
        let sets = [set_layout];
        let pc = [vk::PushConstantRange::default()
            .stage_flags(vk::ShaderStageFlags::COMPUTE)
            .offset(0)
            .size(COMPUTE_PUSH_BYTES)];
        let lci = vk::PipelineLayoutCreateInfo::default()
            .set_layouts(&sets)
            .push_constant_ranges(&pc);
        // SAFETY: valid create info; destroyed in `destroy`.
        let layout = unsafe { gpu.device.create_pipeline_layout(&lci, None) }
            .check("vkCreatePipelineLayout")?;
        Ok(ComputePrograms {
            layout,
            pipelines: HashMap::new(),
        })
    }

    /// Pipelines made so far.
    pub fn count(&self) -> usize {
        self.pipelines.len()
    }

    /// The compute pipeline of `key`, made on first use; a key whose program does not compile
    /// answers the same error every time.
    pub fn get(&mut self, gpu: &Gpu, key: &ShaderKey) -> Result<vk::Pipeline, String> {
        if let Some(p) = self.pipelines.get(key) {
            return p.clone();
        }
        let made = self.make(gpu, key).map_err(|e| e.to_string());
        self.pipelines.insert(*key, made.clone());
        made
    }

    fn make(&self, gpu: &Gpu, key: &ShaderKey) -> Result<vk::Pipeline, VkError> {
        let d = &gpu.device;
        let words = spirv::compile(&compute_glsl(key), "comp")?;
        let ci = vk::ShaderModuleCreateInfo::default().code(&words);
        // SAFETY: valid SPIR-V words from the compiler; the module is destroyed below.
        let module = unsafe { d.create_shader_module(&ci, None) }.check("vkCreateShaderModule")?;
        let stage = vk::PipelineShaderStageCreateInfo::default()
            .stage(vk::ShaderStageFlags::COMPUTE)
            .module(module)
            .name(c"main");
        let ci = [vk::ComputePipelineCreateInfo::default()
            .stage(stage)
            .layout(self.layout)];
        // SAFETY: valid create info; the pipeline is destroyed in `destroy`, the module here,
        // after the creation that uses it returned.
        let made = unsafe {
            let made = d.create_compute_pipelines(vk::PipelineCache::null(), &ci, None);
            d.destroy_shader_module(module, None);
            made
        };
        match made {
            Ok(p) => p
                .into_iter()
                .next()
                .ok_or_else(|| VkError::Setup("no pipeline made".into())),
            Err((_, r)) => Err(VkError::call("vkCreateComputePipelines", r)),
        }
    }

    pub fn destroy(&mut self, gpu: &Gpu) {
        // SAFETY: the device is idle (the worker waits before dropping).
        unsafe {
            for p in self.pipelines.values().flatten() {
                gpu.device.destroy_pipeline(*p, None);
            }
            gpu.device.destroy_pipeline_layout(self.layout, None);
        }
        self.pipelines.clear();
    }
}

/// The push constants of slot `k`'s lookup: P, x and 4 bytes of padding, the pixel (x, y) that
/// the read-back reads as slot `k` (`compute_glsl`'s block: offsets 0, 16, 24).
pub fn push_constants(plan: &Plan, k: usize) -> Vec<u8> {
    let (x, y) = pixel(k);
    let mut b: Vec<u8> = Vec::with_capacity(COMPUTE_PUSH_BYTES as usize);
    for f in plan.p {
        b.extend_from_slice(&f.to_ne_bytes());
    }
    b.extend_from_slice(&plan.x.to_ne_bytes());
    b.extend_from_slice(&[0; 4]);
    b.extend_from_slice(&x.to_ne_bytes());
    b.extend_from_slice(&y.to_ne_bytes());
    b
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn push_constants_follow_the_shaders_block() {
        let plan = Plan {
            key: shadowcheck_plan::paths::plan(
                shadowcheck_model::ApiPath::Vulkan,
                &shadowcheck_plan::test_case::case(shadowcheck_model::Target::T2d, 4, 4, 1),
            )
            .expect("a plan")
            .key,
            p: [0.25, 0.5, 0.75, 1.0],
            x: 2.0,
            dx: [0.0; 4],
            dy: [0.0; 4],
            o: [0, 0],
            note: String::new(),
        };
        let b = push_constants(&plan, 3);
        assert_eq!(b.len(), COMPUTE_PUSH_BYTES as usize);
        let f = |i: usize| f32::from_ne_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]]);
        let n = |i: usize| i32::from_ne_bytes([b[i], b[i + 1], b[i + 2], b[i + 3]]);
        assert_eq!(
            [f(0), f(4), f(8), f(12), f(16)],
            [0.25, 0.5, 0.75, 1.0, 2.0]
        );
        let (x, y) = pixel(3);
        assert_eq!((n(24), n(28)), (x, y));
    }
}
