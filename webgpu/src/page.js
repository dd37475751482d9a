// The WebGPU side of shadowcheck's webgpu:chromium backend. Evaluated once in the worker's page
// (a file:// page: navigator.gpu exists only in a secure context); the worker (shadowcheck-webgpu,
// job.rs) then calls shadowcheck.run(job) per batch and awaits its promise. Everything a lookup
// needs is decided on the Rust side from the lookup plan (WGSL module text, texel values, sampler
// descriptors, instance values, which slot each lookup writes); this page only makes the WebGPU
// calls and reads the results back.
//
// Fragment-stage lookups are instanced draws into the RGBA32F result image (slot s the 2x2 quad at
// column 2*(s % 128), row 2*(s / 128)). Compute-stage lookups (modules with `compute`) are
// dispatches of one workgroup per lookup, after the render pass: entry point "cs" reads its
// slot's values from the instance floats (a read-only storage buffer) and writes its RGBA to
// results[slot] of a storage buffer; after the image is copied to the read-back buffer, each
// compute slot's 16 bytes are copied over its pixel there (copyBufferToBuffer), so every slot is
// read back from the same place. Fragment draws do not change when a job has compute lookups.
//
// Errors: each batch runs inside pushErrorScope("validation"), ("internal") and
// ("out-of-memory") (WebGPU "Error Scopes"); whatever they catch is answered as {errors: [...]}
// and the worker makes every lookup of the batch an error with the message (a validation error is
// a harness bug: it must never pass silently). A lost device (GPUDevice.lost) answers {lost: why}
// and the worker ends; a batch that does not finish within RUN_TIMEOUT_MS answers {lost: ...} too.
globalThis.shadowcheck = (() => {
  const FB = 256;
  const RUN_TIMEOUT_MS = 60000;
  let adapter = null;
  let device = null;
  let lost = null;
  const uncaptured = [];
  let target = null;
  const layouts = new Map(); // view dimension -> {group, pipeline}
  const pipelines = new Map(); // WGSL text -> GPURenderPipeline or GPUComputePipeline
  const computeLayouts = new Map(); // view dimension -> {group, pipeline}
  const writers = new Map(); // depth format -> GPURenderPipeline
  let writerModule = null;

  function bytes(b64) {
    const s = atob(b64);
    const u8 = new Uint8Array(s.length);
    for (let i = 0; i < s.length; i++) u8[i] = s.charCodeAt(i);
    return u8;
  }

  function base64(u8) {
    let s = "";
    for (let i = 0; i < u8.length; i += 0x8000) {
      s += String.fromCharCode.apply(null, u8.subarray(i, i + 0x8000));
    }
    return btoa(s);
  }

  // A buffer holding `u8` (padded to 4 bytes), for `usage`.
  function upload(u8, usage) {
    const size = Math.max(4, Math.ceil(u8.byteLength / 4) * 4);
    const b = device.createBuffer({ size, usage, mappedAtCreation: true });
    new Uint8Array(b.getMappedRange()).set(u8);
    b.unmap();
    return b;
  }

  // opts: {featureLevel, writer (WGSL of the texel writer)}.
  async function init(opts) {
    if (!navigator.gpu) return { error: "no navigator.gpu (not a secure context, or WebGPU disabled)" };
    adapter = await navigator.gpu.requestAdapter({ featureLevel: opts.featureLevel });
    if (!adapter) return { error: "requestAdapter({featureLevel: '" + opts.featureLevel + "'}) returned null" };
    const requiredFeatures = ["depth32float-stencil8", "core-features-and-limits"].filter((f) =>
      adapter.features.has(f),
    );
    device = await adapter.requestDevice({ requiredFeatures });
    device.lost.then((info) => {
      if (!lost) lost = "GPUDevice.lost (" + info.reason + "): " + info.message;
    });
    device.addEventListener("uncapturederror", (ev) => {
      uncaptured.push(ev.error.constructor.name + ": " + ev.error.message);
    });
    target = device.createTexture({
      size: [FB, FB],
      format: "rgba32float",
      usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC,
    });
    writerModule = device.createShaderModule({ code: opts.writer });
    const info = adapter.info || {};
    return {
      vendor: info.vendor || "",
      architecture: info.architecture || "",
      device: info.device || "",
      description: info.description || "",
      isFallbackAdapter: !!(info.isFallbackAdapter ?? adapter.isFallbackAdapter),
      features: [...device.features].sort(),
      adapterFeatures: [...adapter.features].sort(),
      maxTextureDimension2D: device.limits.maxTextureDimension2D,
      maxTextureArrayLayers: device.limits.maxTextureArrayLayers,
      userAgent: navigator.userAgent,
    };
  }

  // The bind group layout and pipeline layout of a sampled view dimension.
  function layoutFor(view) {
    let l = layouts.get(view);
    if (!l) {
      const group = device.createBindGroupLayout({
        entries: [
          { binding: 0, visibility: GPUShaderStage.FRAGMENT, texture: { sampleType: "depth", viewDimension: view } },
          { binding: 1, visibility: GPUShaderStage.FRAGMENT, sampler: { type: "comparison" } },
        ],
      });
      l = { group, pipeline: device.createPipelineLayout({ bindGroupLayouts: [group] }) };
      layouts.set(view, l);
    }
    return l;
  }

  // The bind group layout and pipeline layout of a compute module of a sampled view dimension:
  // the texture and the sampler, and the buffers of job.computeBindings ([name, binding, type]).
  function computeLayoutFor(view, bindings) {
    let l = computeLayouts.get(view);
    if (!l) {
      const group = device.createBindGroupLayout({
        entries: [
          { binding: 0, visibility: GPUShaderStage.COMPUTE, texture: { sampleType: "depth", viewDimension: view } },
          { binding: 1, visibility: GPUShaderStage.COMPUTE, sampler: { type: "comparison" } },
        ].concat(bindings.map(([, binding, type]) => ({ binding, visibility: GPUShaderStage.COMPUTE, buffer: { type } }))),
      });
      l = { group, pipeline: device.createPipelineLayout({ bindGroupLayouts: [group] }) };
      computeLayouts.set(view, l);
    }
    return l;
  }

  // The compute pipeline of a compute module, cached by its text.
  function computePipelineFor(m, bindings) {
    let p = pipelines.get(m.wgsl);
    if (!p) {
      const module = device.createShaderModule({ code: m.wgsl });
      p = device.createComputePipeline({
        layout: computeLayoutFor(m.view, bindings).pipeline,
        compute: { module, entryPoint: "cs" },
      });
      pipelines.set(m.wgsl, p);
    }
    return p;
  }

  // The lookup pipeline of a module (job.modules[i]), cached by its text.
  function pipelineFor(m, attributes, stride) {
    let p = pipelines.get(m.wgsl);
    if (!p) {
      const module = device.createShaderModule({ code: m.wgsl });
      p = device.createRenderPipeline({
        layout: layoutFor(m.view).pipeline,
        vertex: {
          module,
          entryPoint: "vs",
          buffers: [
            {
              arrayStride: stride,
              stepMode: "instance",
              attributes: attributes.map(([shaderLocation, format, at]) => ({ shaderLocation, format, offset: 4 * at })),
            },
          ],
        },
        fragment: { module, entryPoint: "fs", targets: [{ format: "rgba32float" }] },
        primitive: { topology: "triangle-list" },
      });
      pipelines.set(m.wgsl, p);
    }
    return p;
  }

  // The texel writer of a depth format: points whose fragments write frag_depth.
  function writerFor(format) {
    let p = writers.get(format);
    if (!p) {
      p = device.createRenderPipeline({
        layout: "auto",
        vertex: {
          module: writerModule,
          entryPoint: "vs",
          buffers: [
            {
              arrayStride: 12,
              attributes: [
                { shaderLocation: 0, format: "float32x2", offset: 0 },
                { shaderLocation: 1, format: "float32", offset: 8 },
              ],
            },
          ],
        },
        fragment: { module: writerModule, entryPoint: "fs", targets: [] },
        primitive: { topology: "point-list" },
        depthStencil: { format, depthWriteEnabled: true, depthCompare: "always" },
      });
      writers.set(format, p);
    }
    return p;
  }

  // Writes every level and layer of texture `t` (job.textures[i]) with its points.
  function writeTexels(enc, tex, t, points) {
    for (const s of t.subresources) {
      const view = tex.createView({
        dimension: "2d",
        baseMipLevel: s.level,
        mipLevelCount: 1,
        baseArrayLayer: s.layer,
        arrayLayerCount: 1,
      });
      const ds = { view, depthClearValue: 0, depthLoadOp: "clear", depthStoreOp: "store" };
      if (t.hasStencil) {
        ds.stencilClearValue = 0;
        ds.stencilLoadOp = "clear";
        ds.stencilStoreOp = "store";
      }
      const pass = enc.beginRenderPass({ colorAttachments: [], depthStencilAttachment: ds });
      pass.setPipeline(writerFor(t.format));
      pass.setVertexBuffer(0, points);
      pass.draw(s.count, 1, s.first, 0);
      pass.end();
    }
  }

  function withTimeout(promise, what) {
    let timer = null;
    const late = new Promise((resolve) => {
      timer = setTimeout(() => resolve({ lost: what + " did not finish within " + RUN_TIMEOUT_MS / 1000 + " s" }), RUN_TIMEOUT_MS);
    });
    return Promise.race([promise.finally(() => clearTimeout(timer)), late]);
  }

  // job: {modules: [{wgsl, view, compute}], textures: [...], points, instances, attributes, stride,
  // computeBindings,
  // draws: [{texture, module, first, count}], slots}; opts: {fault}.
  async function runJob(job, opts) {
    if (lost) return { lost };
    const made = [];
    const buffers = [];
    device.pushErrorScope("out-of-memory");
    device.pushErrorScope("internal");
    device.pushErrorScope("validation");
    let answer = null;
    let thrown = null;
    const reads = [];
    try {
      const points = upload(bytes(job.points), GPUBufferUsage.VERTEX);
      const instances = upload(bytes(job.instances), GPUBufferUsage.VERTEX);
      buffers.push(points, instances);
      const enc = device.createCommandEncoder();
      const groups = [];
      const views = [];
      const samplers = [];
      for (const t of job.textures) {
        let usage = GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.RENDER_ATTACHMENT;
        if (t.readback) usage |= GPUTextureUsage.COPY_SRC;
        const tex = device.createTexture({
          size: [t.width, t.height, t.layers],
          mipLevelCount: t.levels,
          format: t.format,
          usage,
          textureBindingViewDimension: t.view,
        });
        made.push(tex);
        writeTexels(enc, tex, t, points);
        const sampler = device.createSampler(
          opts.fault === "invalid-sampler" ? { ...t.sampler, lodMinClamp: -1 } : t.sampler,
        );
        const view = tex.createView({
          dimension: t.view,
          aspect: "depth-only",
          baseMipLevel: 0,
          mipLevelCount: t.viewLevels,
        });
        views.push(view);
        samplers.push(sampler);
        groups.push(
          device.createBindGroup({
            layout: layoutFor(t.view).group,
            entries: [
              { binding: 0, resource: view },
              { binding: 1, resource: sampler },
            ],
          }),
        );
      }
      const pass = enc.beginRenderPass({
        colorAttachments: [
          { view: target.createView(), clearValue: [0, 0, 0, 0], loadOp: "clear", storeOp: "store" },
        ],
      });
      pass.setVertexBuffer(0, instances);
      const draws = job.draws.filter((d) => !job.modules[d.module].compute);
      const dispatches = job.draws.filter((d) => job.modules[d.module].compute);
      for (const d of draws) {
        pass.setPipeline(pipelineFor(job.modules[d.module], job.attributes, job.stride));
        pass.setBindGroup(0, groups[d.texture]);
        pass.draw(6, d.count, 0, d.first);
      }
      pass.end();
      // The compute lookups: one dispatch per compute draw, workgroup i is slot d.first + i; the
      // dispatch's first slot is a uniform (one 256-byte entry each, the offset alignment).
      let computed = null;
      if (dispatches.length > 0) {
        const lookups = upload(bytes(job.instances), GPUBufferUsage.STORAGE);
        computed = device.createBuffer({
          size: job.slots * 16,
          usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC,
        });
        const align = device.limits.minUniformBufferOffsetAlignment;
        const firsts = new Uint32Array((dispatches.length * align) / 4);
        dispatches.forEach((d, k) => (firsts[(k * align) / 4] = d.first));
        const first = upload(new Uint8Array(firsts.buffer), GPUBufferUsage.UNIFORM);
        buffers.push(lookups, computed, first);
        const buffersOf = { lookups, results: computed, first };
        const cpass = enc.beginComputePass();
        dispatches.forEach((d, k) => {
          const m = job.modules[d.module];
          cpass.setPipeline(computePipelineFor(m, job.computeBindings));
          cpass.setBindGroup(
            0,
            device.createBindGroup({
              layout: computeLayoutFor(m.view, job.computeBindings).group,
              entries: [
                { binding: 0, resource: views[d.texture] },
                { binding: 1, resource: samplers[d.texture] },
              ].concat(
                job.computeBindings.map(([name, binding]) => ({
                  binding,
                  resource:
                    name === "first"
                      ? { buffer: first, offset: k * align, size: 16 }
                      : { buffer: buffersOf[name] },
                })),
              ),
            }),
          );
          cpass.dispatchWorkgroups(d.count);
        });
        cpass.end();
      }
      // The rows of the result image that hold slots, then level 0 of each texture read back.
      const rows = Math.min(FB, 2 * Math.ceil(job.slots / (FB / 2)));
      const result = device.createBuffer({
        size: Math.max(1, rows) * FB * 16,
        usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ,
      });
      buffers.push(result);
      if (rows > 0) {
        enc.copyTextureToBuffer({ texture: target }, { buffer: result, bytesPerRow: FB * 16, rowsPerImage: rows }, [FB, rows, 1]);
      }
      // Each compute slot's result over its pixel (x, y) = (2 * (s % 128), 2 * (s / 128)).
      for (const d of dispatches) {
        for (let s = d.first; s < d.first + d.count; s++) {
          const x = 2 * (s % (FB / 2));
          const y = 2 * Math.floor(s / (FB / 2));
          enc.copyBufferToBuffer(computed, s * 16, result, (y * FB + x) * 16, 16);
        }
      }
      const stored = [];
      job.textures.forEach((t, i) => {
        if (!t.readback) {
          stored.push(null);
          return;
        }
        const bytesPerRow = Math.ceil((t.width * t.readback) / 256) * 256;
        const b = device.createBuffer({
          size: bytesPerRow * t.height * t.layers,
          usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ,
        });
        buffers.push(b);
        enc.copyTextureToBuffer(
          { texture: made[i], mipLevel: 0, aspect: "depth-only" },
          { buffer: b, bytesPerRow, rowsPerImage: t.height },
          [t.width, t.height, t.layers],
        );
        stored.push({ buffer: b, bytesPerRow, t });
      });
      device.queue.submit([enc.finish()]);
      if (opts.fault === "destroy-device") device.destroy();
      reads.push(result.mapAsync(GPUMapMode.READ));
      for (const s of stored) if (s) reads.push(s.buffer.mapAsync(GPUMapMode.READ));
      answer = { result, rows, stored };
    } catch (e) {
      thrown = String(e && e.stack ? e.stack : e);
    }
    const scoped = [];
    for (const scope of ["validation", "internal", "out-of-memory"]) {
      const e = await device.popErrorScope();
      if (e) scoped.push(scope + " error: " + e.message);
    }
    let mapped = null;
    try {
      await Promise.all(reads);
    } catch (e) {
      mapped = String(e);
      // A lost device rejects the mapping before GPUDevice.lost has settled: wait for it a while.
      await Promise.race([device.lost, new Promise((r) => setTimeout(r, 1000))]);
    }
    if (lost) return { lost };
    const errors = scoped.concat(uncaptured.splice(0));
    if (thrown) errors.push("exception: " + thrown);
    if (mapped && errors.length === 0) errors.push("mapAsync failed: " + mapped);
    let out = { errors };
    if (errors.length === 0 && answer) {
      const px = new Uint8Array(answer.result.getMappedRange());
      const slots = new Uint8Array(job.slots * 16);
      for (let s = 0; s < job.slots; s++) {
        const x = 2 * (s % (FB / 2));
        const y = 2 * Math.floor(s / (FB / 2));
        slots.set(px.subarray((y * FB + x) * 16, (y * FB + x) * 16 + 16), s * 16);
      }
      const texels = answer.stored.map((s) => {
        if (!s) return null;
        const src = new Uint8Array(s.buffer.getMappedRange());
        const row = s.t.width * s.t.readback;
        const packed = new Uint8Array(row * s.t.height * s.t.layers);
        for (let r = 0; r < s.t.height * s.t.layers; r++) {
          packed.set(src.subarray(r * s.bytesPerRow, r * s.bytesPerRow + row), r * row);
        }
        return base64(packed);
      });
      out = { errors, pixels: base64(slots), stored: texels };
    }
    for (const b of buffers) b.destroy();
    for (const t of made) t.destroy();
    return out;
  }

  function run(job, opts) {
    return withTimeout(runJob(job, opts || {}), "the batch");
  }

  return { init, run };
})();
