//! A batch's lookups planned, their textures described, and both dealt into submissions.

use super::{groups, plan_job, result, Planned, VkWorker};
use crate::device::take_messages;
use crate::draw::{Lookup, TextureSpec, MAX_TEXTURES};
use crate::VkError;
use shadowcheck_plan::layout::CAPACITY;
use shadowcheck_plan::{Answer, Job};

impl VkWorker {
    /// One answer per job: a Skip where the texture or the lookup does not run here, else what
    /// was drawn (an Error for a submission that failed or made the validation layer speak).
    pub(super) fn plan_and_draw(&mut self, jobs: &[Job]) -> Vec<Option<Answer>> {
        let mut out: Vec<Option<Answer>> = vec![None; jobs.len()];
        let mut specs: Vec<TextureSpec> = vec![];
        let mut planned: Vec<Planned> = vec![];
        for r in groups(jobs) {
            match self.texture_spec(jobs[r.start].case) {
                Err(why) => r.for_each(|i| out[i] = Some(Answer::Skip(why.clone()))),
                Ok(spec) => {
                    let texture = specs.len();
                    let mut any = false;
                    for i in r {
                        match plan_job(&jobs[i]).and_then(|p| self.limits(&p).map(|_| p)) {
                            Ok(plan) => {
                                planned.push(Planned {
                                    job: i,
                                    texture,
                                    plan,
                                });
                                any = true;
                            }
                            Err(why) => out[i] = Some(Answer::Skip(why)),
                        }
                    }
                    if any {
                        specs.push(spec);
                    }
                }
            }
        }
        // Submissions: consecutive textures, at most MAX_TEXTURES and CAPACITY lookups each.
        let mut start = 0;
        while start < planned.len() {
            let t0 = planned[start].texture;
            let mut end = start;
            while end < planned.len() {
                let p = &planned[end];
                // Textures are consecutive: the first lookup of one texture too many ends it.
                if end > start && (end - start >= CAPACITY || p.texture - t0 >= MAX_TEXTURES) {
                    break;
                }
                end += 1;
            }
            let chunk = &planned[start..end];
            let t1 = chunk.last().map_or(t0, |p| p.texture + 1);
            self.submit_chunk(jobs, &specs[t0..t1], t0, chunk, &mut out);
            start = end;
            if self.lost.is_some() {
                break;
            }
        }
        if let Some(why) = &self.lost {
            for p in &planned[start..] {
                out[p.job] = Some(Answer::Error(format!("the Vulkan device is lost ({why})")));
            }
        }
        out
    }

    /// [`crate::TEST_FAULT_ENV`]: a sampler with anisotropy enabled on a device created without
    /// the samplerAnisotropy feature (VUID-VkSamplerCreateInfo-anisotropyEnable-01070), destroyed
    /// at once; drivers ignore the request, the validation layer reports it.
    fn invalid_sampler(&self) {
        let d = &self.renderer.gpu.device;
        let sci = ash::vk::SamplerCreateInfo::default()
            .anisotropy_enable(true)
            .max_anisotropy(4.0);
        // SAFETY: a valid device and create info; the sampler is destroyed before anything uses it.
        if let Ok(s) = unsafe { d.create_sampler(&sci, None) } {
            // SAFETY: `s` was created on `d` and is in no descriptor set or command buffer.
            unsafe { d.destroy_sampler(s, None) };
        }
    }

    fn submit_chunk(
        &mut self,
        jobs: &[Job],
        specs: &[TextureSpec],
        t0: usize,
        chunk: &[Planned],
        out: &mut [Option<Answer>],
    ) {
        let lookups: Vec<Lookup> = chunk
            .iter()
            .map(|p| Lookup {
                texture: p.texture - t0,
                plan: &p.plan,
            })
            .collect();
        if std::env::var(crate::TEST_FAULT_ENV).is_ok_and(|v| v == "invalid-sampler") {
            self.invalid_sampler();
        }
        let drawn = self.renderer.draw(specs, &lookups);
        let mut messages = std::mem::take(&mut self.pending);
        messages.extend(take_messages());
        let fail = |out: &mut [Option<Answer>], msg: &str| {
            for p in chunk {
                out[p.job] = Some(Answer::Error(msg.to_string()));
            }
        };
        match drawn {
            Err(VkError::DeviceLost(why)) => {
                fail(out, &format!("the Vulkan device is lost ({why})"));
                self.lost = Some(why);
            }
            Err(e) => fail(out, &format!("vulkan: {e}")),
            Ok(_) if !messages.is_empty() => {
                fail(out, &format!("validation layer: {}", messages.join(" | ")))
            }
            Ok((rgba, stored)) => {
                for (p, v) in chunk.iter().zip(rgba) {
                    let texels = (!jobs[p.job].point)
                        .then(|| stored.get(p.texture - t0).cloned())
                        .flatten();
                    out[p.job] = Some(match v {
                        Ok(v) => Answer::Observation(vec![result(v, &p.plan, texels)], vec![]),
                        Err(msg) => Answer::Error(msg),
                    });
                }
            }
        }
    }
}
