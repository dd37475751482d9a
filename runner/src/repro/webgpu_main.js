// The WebGPU page's own part: adapter and device, the texture written through frag_depth, the
// sampler and view, the lookup (one draw of slot 0's quad, or, for a compute-stage module, one
// dispatch of slot 0's workgroup: COMPUTE_BINDINGS not null), the read-back and the verdict.
// Everything runs inside pushErrorScope("validation"): an error is printed and no verdict is given.
// A buffer holding `data` (a typed array), for `usage`.
function upload(device, data, usage) {
  const size = Math.max(4, Math.ceil(data.byteLength / 4) * 4);
  const b = device.createBuffer({ size, usage, mappedAtCreation: true });
  new Uint8Array(b.getMappedRange()).set(new Uint8Array(data.buffer, data.byteOffset, data.byteLength));
  b.unmap();
  return b;
}

// The fragment-stage lookup: the case's sampler and view, slot 0's quad in a 2x2 RGBA32F target
// cleared to -1, copied to `read`.
function drawLookup(device, enc, tex, read) {
  const group = device.createBindGroupLayout({ entries: [
    { binding: 0, visibility: GPUShaderStage.FRAGMENT, texture: { sampleType: "depth", viewDimension: TEXTURE.view } },
    { binding: 1, visibility: GPUShaderStage.FRAGMENT, sampler: { type: "comparison" } },
  ] });
  const module = device.createShaderModule({ code: LOOKUP });
  const pipeline = device.createRenderPipeline({
    layout: device.createPipelineLayout({ bindGroupLayouts: [group] }),
    vertex: { module, entryPoint: "vs", buffers: [{ arrayStride: 4 * INSTANCE.length, stepMode: "instance",
      attributes: ATTRIBUTES.map(([shaderLocation, format, at]) => ({ shaderLocation, format, offset: 4 * at })) }] },
    fragment: { module, entryPoint: "fs", targets: [{ format: "rgba32float" }] },
    primitive: { topology: "triangle-list" },
  });
  const bind = device.createBindGroup({ layout: group, entries: [
    { binding: 0, resource: tex.createView({ dimension: TEXTURE.view, aspect: "depth-only", baseMipLevel: 0, mipLevelCount: TEXTURE.viewLevels }) },
    { binding: 1, resource: device.createSampler(SAMPLER) },
  ] });
  const target = device.createTexture({ size: [2, 2], format: "rgba32float", usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC });
  const pass = enc.beginRenderPass({ colorAttachments: [{ view: target.createView(), clearValue: [-1, -1, -1, -1], loadOp: "clear", storeOp: "store" }] });
  pass.setPipeline(pipeline);
  pass.setBindGroup(0, bind);
  pass.setVertexBuffer(0, upload(device, INSTANCE, GPUBufferUsage.VERTEX));
  pass.draw(6, 1, 0, 0);
  pass.end();
  enc.copyTextureToBuffer({ texture: target }, { buffer: read, bytesPerRow: 256, rowsPerImage: 2 }, [2, 2, 1]);
}

// The compute-stage lookup, as the worker dispatches it (shadowcheck-webgpu page.js): the 2x2
// RGBA32F target cleared to -1 by a render pass with no draw (the worker's pass, which draws only
// fragment-stage lookups), then one compute pass, one dispatch of one workgroup (slot 0): the
// module's `cs` reads slot 0's values from `lookups` (read-only storage: INSTANCE), its first slot
// (0) from `first` (uniform, one minUniformBufferOffsetAlignment entry) and writes its RGBA to
// results[0] (storage); the target is copied to `read` and results[0]'s 16 bytes over pixel (0, 0)
// there. No draw samples the texture before the dispatch.
function dispatchLookup(device, enc, tex, read) {
  const group = device.createBindGroupLayout({ entries: [
    { binding: 0, visibility: GPUShaderStage.COMPUTE, texture: { sampleType: "depth", viewDimension: TEXTURE.view } },
    { binding: 1, visibility: GPUShaderStage.COMPUTE, sampler: { type: "comparison" } },
  ].concat(COMPUTE_BINDINGS.map(([, binding, type]) => ({ binding, visibility: GPUShaderStage.COMPUTE, buffer: { type } }))) });
  const module = device.createShaderModule({ code: LOOKUP });
  const pipeline = device.createComputePipeline({
    layout: device.createPipelineLayout({ bindGroupLayouts: [group] }),
    compute: { module, entryPoint: "cs" },
  });
  const target = device.createTexture({ size: [2, 2], format: "rgba32float", usage: GPUTextureUsage.RENDER_ATTACHMENT | GPUTextureUsage.COPY_SRC });
  const pass = enc.beginRenderPass({ colorAttachments: [{ view: target.createView(), clearValue: [-1, -1, -1, -1], loadOp: "clear", storeOp: "store" }] });
  pass.end();
  const lookups = upload(device, INSTANCE, GPUBufferUsage.STORAGE);
  const results = device.createBuffer({ size: 16, usage: GPUBufferUsage.STORAGE | GPUBufferUsage.COPY_SRC });
  const align = device.limits.minUniformBufferOffsetAlignment;
  const first = upload(device, new Uint32Array(align / 4), GPUBufferUsage.UNIFORM);
  const buffers = { lookups, results, first };
  const bind = device.createBindGroup({ layout: group, entries: [
    { binding: 0, resource: tex.createView({ dimension: TEXTURE.view, aspect: "depth-only", baseMipLevel: 0, mipLevelCount: TEXTURE.viewLevels }) },
    { binding: 1, resource: device.createSampler(SAMPLER) },
  ].concat(COMPUTE_BINDINGS.map(([name, binding]) => ({
    binding,
    resource: name === "first" ? { buffer: first, offset: 0, size: 16 } : { buffer: buffers[name] },
  }))) });
  const cpass = enc.beginComputePass();
  cpass.setPipeline(pipeline);
  cpass.setBindGroup(0, bind);
  cpass.dispatchWorkgroups(1);
  cpass.end();
  enc.copyTextureToBuffer({ texture: target }, { buffer: read, bytesPerRow: 256, rowsPerImage: 2 }, [2, 2, 1]);
  enc.copyBufferToBuffer(results, 0, read, 0, 16);
}

async function main() {
  if (!navigator.gpu) throw new Error("no navigator.gpu (WebGPU disabled, or not a secure context)");
  const adapter = await navigator.gpu.requestAdapter({ featureLevel: FEATURE_LEVEL });
  if (!adapter) throw new Error("requestAdapter({featureLevel: '" + FEATURE_LEVEL + "'}) returned null");
  const info = adapter.info || {};
  print("WEBGPU_ADAPTER: " + [info.vendor, info.architecture, info.device, info.description].filter((x) => x).join(", ") +
    (info.isFallbackAdapter ? " (fallback adapter)" : ""));
  print("BROWSER: " + navigator.userAgent);
  const requiredFeatures = [];
  if (TEXTURE.format === "depth32float-stencil8") {
    if (!adapter.features.has("depth32float-stencil8")) throw new Error("the adapter lacks the depth32float-stencil8 feature");
    requiredFeatures.push("depth32float-stencil8");
  }
  const device = await adapter.requestDevice({ requiredFeatures });
  device.pushErrorScope("validation");
  const enc = device.createCommandEncoder();
  // The texture, every level and layer written by points whose fragments write frag_depth.
  const tex = device.createTexture({
    size: [TEXTURE.width, TEXTURE.height, TEXTURE.layers],
    mipLevelCount: TEXTURE.levels,
    format: TEXTURE.format,
    usage: GPUTextureUsage.TEXTURE_BINDING | GPUTextureUsage.RENDER_ATTACHMENT,
    textureBindingViewDimension: TEXTURE.view,
  });
  const writerModule = device.createShaderModule({ code: WRITER });
  const writer = device.createRenderPipeline({
    layout: "auto",
    vertex: {
      module: writerModule,
      entryPoint: "vs",
      buffers: [{ arrayStride: 12, attributes: [
        { shaderLocation: 0, format: "float32x2", offset: 0 },
        { shaderLocation: 1, format: "float32", offset: 8 },
      ] }],
    },
    fragment: { module: writerModule, entryPoint: "fs", targets: [] },
    primitive: { topology: "point-list" },
    depthStencil: { format: TEXTURE.format, depthWriteEnabled: true, depthCompare: "always" },
  });
  const points = upload(device, POINTS, GPUBufferUsage.VERTEX);
  for (const s of TEXTURE.subresources) {
    const view = tex.createView({ dimension: "2d", baseMipLevel: s.level, mipLevelCount: 1, baseArrayLayer: s.layer, arrayLayerCount: 1 });
    const ds = { view, depthClearValue: 0, depthLoadOp: "clear", depthStoreOp: "store" };
    if (TEXTURE.hasStencil) Object.assign(ds, { stencilClearValue: 0, stencilLoadOp: "clear", stencilStoreOp: "store" });
    const pass = enc.beginRenderPass({ colorAttachments: [], depthStencilAttachment: ds });
    pass.setPipeline(writer);
    pass.setVertexBuffer(0, points);
    pass.draw(s.count, 1, s.first, 0);
    pass.end();
  }
  const read = device.createBuffer({ size: 512, usage: GPUBufferUsage.COPY_DST | GPUBufferUsage.MAP_READ });
  if (COMPUTE_BINDINGS === null) drawLookup(device, enc, tex, read);
  else dispatchLookup(device, enc, tex, read);
  device.queue.submit([enc.finish()]);
  const err = await device.popErrorScope();
  if (err) throw new Error("validation error: " + err.message);
  await read.mapAsync(GPUMapMode.READ);
  judge([...new Float32Array(read.getMappedRange(), 0, 4)]);
}

main()
  .catch((e) => print("setup failed: " + e))
  .finally(() => console.log(END));
