//! The comparison itself, per specification: which functions exist, which operand is compared
//! with which, how Dref and Dt are clamped, and what a failing texel contributes.
//!
//! | spec | functions | clamping | fail value |
//! | --- | --- | --- | --- |
//! | sgix, sgix_ambient | TEXTURE_LEQUAL_R_SGIX: texel ≤ R; TEXTURE_GEQUAL_R_SGIX: texel ≥ R | unstated; **chosen**: as ARB (R and Dt clamped for fixed-point formats, following the NVIDIA note) | 0.0 / SHADOW_AMBIENT_SGIX |
//! | arb, arb_ambient | LEQUAL: R ≤ Dt, GEQUAL: R ≥ Dt | R clamped, Dt in [0,1] (ARB_shadow 3.8.13.1); for floating-point depth formats ARB_depth_buffer_float rev 7 removes the clamp | 0.0 / TEXTURE_COMPARE_FAIL_VALUE_ARB |
//! | ext_funcs | the eight of EXT_shadow_funcs, R against Dt | as arb | 0.0 |
//! | es2_ext | the eight | Dt and Dref **always** clamped (EXT_shadow_samplers 3.7.14.1) | 0.0 |
//! | gl46, gles32 | the eight (Table 8.23 / 8.22) | only for fixed-point depth formats (§8.23.1 / §8.20.1) | 0.0 |
//! | vulkan | the eight VkCompareOp, Dref the reference and Dtex the test value | Dref only, and only for UNORM formats (Depth Compare Operation) | 0.0 |
//! | webgpu | the eight GPUCompareFunction values, depth_ref the provided value and the texel the sampled value | none (no clamp is stated; **chosen**: the literal reading) | 0.0 |

use crate::faults::{Fault, Faults};
use crate::SoftError;
use shadowcheck_model::{CompareFunc, Format, Spec};

/// A resolved comparison: which of Dref and Dt must relate how for the texel to pass.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CompareOp {
    Never,
    /// Dref < Dt
    Less,
    /// Dref = Dt
    Equal,
    /// Dref ≤ Dt
    Lequal,
    /// Dref > Dt
    Greater,
    /// Dref ≠ Dt
    Notequal,
    /// Dref ≥ Dt
    Gequal,
    Always,
    /// SGIX_shadow TEXTURE_LEQUAL_R_SGIX: texel ≤ R.
    TexelLeR,
    /// SGIX_shadow TEXTURE_GEQUAL_R_SGIX: texel ≥ R.
    TexelGeR,
}

/// Maps TEXTURE_COMPARE_FUNC to the comparison the spec defines, or an error naming a function the
/// spec does not have (the GL would raise INVALID_ENUM / INVALID_OPERATION and keep the old value).
pub fn resolve_op(spec: Spec, func: CompareFunc, faults: Faults) -> Result<CompareOp, SoftError> {
    use CompareFunc as C;
    let defined = match spec {
        // SGIX_shadow "Table 3.8": TEXTURE_LEQUAL_R_SGIX, TEXTURE_GEQUAL_R_SGIX only.
        Spec::Sgix | Spec::SgixAmbient => matches!(func, C::LequalRSgix | C::GequalRSgix),
        // ARB_shadow table 3.19: LEQUAL, GEQUAL only.
        Spec::Arb | Spec::ArbAmbient => matches!(func, C::Lequal | C::Gequal),
        // EXT_shadow_funcs, EXT_shadow_samplers, GL 4.6 Table 8.17, ES 3.2 Table 8.19: the eight.
        Spec::ExtFuncs | Spec::Es2Ext | Spec::Gl46 | Spec::Gles32 => {
            !matches!(func, C::LequalRSgix | C::GequalRSgix)
        }
        // Vulkan: VkSamplerCreateInfo::compareOp is a VkCompareOp, NEVER .. ALWAYS; "reference"
        // is Dref, "test" is Dtex, so LESS passes when Dref < Dtex as in GL's table.
        Spec::Vulkan => !matches!(func, C::LequalRSgix | C::GequalRSgix),
        // WebGPU, Samplers: GPUSamplerDescriptor: "enum GPUCompareFunction { "never", "less",
        // "equal", "less-equal", "greater", "not-equal", "greater-equal", "always" }" — the
        // eight, and no SGIX operator. Which operand is which: see `webgpu_op` below.
        Spec::WebGpu => !matches!(func, C::LequalRSgix | C::GequalRSgix),
    };
    if !defined {
        return Err(SoftError::CompareFunc { spec, func });
    }
    let mut op = match func {
        C::Never => CompareOp::Never,
        C::Less => CompareOp::Less,
        C::Equal => CompareOp::Equal,
        C::Lequal => CompareOp::Lequal,
        C::Greater => CompareOp::Greater,
        C::Notequal => CompareOp::Notequal,
        C::Gequal => CompareOp::Gequal,
        C::Always => CompareOp::Always,
        C::LequalRSgix => CompareOp::TexelLeR,
        C::GequalRSgix => CompareOp::TexelGeR,
    };
    if faults.has(Fault::LequalGequalSwapped) {
        op = match op {
            CompareOp::Lequal => CompareOp::Gequal,
            CompareOp::Gequal => CompareOp::Lequal,
            o => o,
        };
    }
    if faults.has(Fault::LessAsLequal) && op == CompareOp::Less {
        op = CompareOp::Lequal;
    }
    if faults.has(Fault::GreaterAsGequal) && op == CompareOp::Greater {
        op = CompareOp::Gequal;
    }
    if faults.has(Fault::AlwaysNeverSwapped) {
        op = match op {
            CompareOp::Always => CompareOp::Never,
            CompareOp::Never => CompareOp::Always,
            o => o,
        };
    }
    if spec == Spec::WebGpu {
        op = webgpu_op(op, faults);
    }
    if faults.has(Fault::SgixOperatorsReversed) {
        // ARB_shadow issue 2's reading: TEXTURE_LEQUAL_R_SGIX means R ≤ texture.
        op = match op {
            CompareOp::TexelLeR => CompareOp::Lequal,
            CompareOp::TexelGeR => CompareOp::Gequal,
            o => o,
        };
    }
    Ok(op)
}

/// WebGPU, Samplers: GPUSamplerDescriptor: "If a comparison sampler is used in a shader, the
/// `depth_ref` is compared to the fetched texel value", and e.g. for "less": "A provided value
/// passes the comparison test if it is less than the sampled value." The provided value is
/// depth_ref (WGSL textureSampleCompare: "The reference value to compare the sampled
/// depth value against"), the sampled value the texel: "less" passes when depth_ref < texel,
/// which is [`CompareOp::Less`] (Dref < Dt), and likewise for the other six ("equal": "equal
/// to the sampled value", "less-equal", "greater", "not-equal", "greater-equal"; "never":
/// "Comparison tests never pass", "always": "Comparison tests always pass"). The mapping is
/// the identity; [`Fault::WgpuCompareOperandsSwapped`] reads the sentences the other way round
/// (texel OP depth_ref).
fn webgpu_op(op: CompareOp, faults: Faults) -> CompareOp {
    if !faults.has(Fault::WgpuCompareOperandsSwapped) {
        return op;
    }
    match op {
        CompareOp::Less => CompareOp::Greater,
        CompareOp::Greater => CompareOp::Less,
        CompareOp::Lequal => CompareOp::Gequal,
        CompareOp::Gequal => CompareOp::Lequal,
        o => o,
    }
}

/// Which operands are clamped to [0, 1] before the comparison.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ClampRule {
    pub dref: bool,
    pub dt: bool,
}

/// The clamping rule of `spec` for a texture of `format` (see the module table).
pub fn clamp_rule(spec: Spec, format: Format, faults: Faults) -> ClampRule {
    let fixed = format.is_fixed_point();
    let (mut dref, mut dt) = match spec {
        // EXT_shadow_samplers 3.7.14.1: "D_t and D_ref are clamped to the range [0,1]".
        Spec::Es2Ext => (true, true),
        // Vulkan §16 Depth Compare Operation: "If the image being sampled has an unsigned
        // normalized fixed-point format, then Dref is clamped to [0,1] before the compare
        // operation." Nothing is said of Dtex: a UNORM texel is in [0,1] by its encoding, and a
        // D32_SFLOAT one is used as stored.
        Spec::Vulkan => (fixed, false),
        // WebGPU, Samplers: GPUSamplerDescriptor (GPUCompareFunction) and WGSL
        // textureSampleCompare ("depth_ref: The reference value to compare the sampled depth
        // value against") say nothing of clamping depth_ref, for any format. Chosen: the literal
        // reading, no clamp (the other reading, Vulkan's clamp for unorm formats, is what D3D12
        // and Vulkan backends may do; a grid accepts both). The texel is used as stored: a
        // depth16unorm / 24-bit texel lies in [0, 1] by its encoding, and a depth32float one
        // is written by a render pass (WebGPU, Output Merging: "The depth input to this
        // stage, if any, is clamped to the current [[viewport]] depth range").
        Spec::WebGpu => (false, false),
        // GL 4.6 §8.23.1, ES 3.2 §8.20.1, ARB_depth_buffer_float rev 7 (which also amends the
        // ARB_shadow text for floating-point formats): clamp only fixed-point depth.
        // SGIX: unstated; chosen as ARB (NVIDIA clamps R).
        _ => (fixed, fixed),
    };
    if faults.has(Fault::RefClampedForFloat) {
        dref = true;
    }
    if faults.has(Fault::RefNotClamped) {
        dref = false;
    }
    if faults.has(Fault::DtClampedForFloat) {
        dt = true;
    }
    if faults.has(Fault::DtNotClamped) {
        dt = false;
    }
    ClampRule { dref, dt }
}

/// Tolerance used by [`Fault::EqualWithTolerance`].
const FAULT_EQUAL_TOLERANCE: f32 = 1.0 / 4096.0;

/// Does a texel with (already clamped) depth `dt` pass against reference `dref`? IEEE semantics:
/// every ordered comparison with a NaN is false, NOTEQUAL with a NaN is true.
#[inline(always)]
pub fn passes(op: CompareOp, dref: f32, dt: f32, faults: Faults) -> bool {
    match op {
        CompareOp::Never => false,
        CompareOp::Always => true,
        CompareOp::Less => dref < dt,
        CompareOp::Lequal => dref <= dt,
        CompareOp::Greater => dref > dt,
        CompareOp::Gequal => dref >= dt,
        CompareOp::Equal => {
            if faults.has(Fault::EqualWithTolerance) {
                (dref - dt).abs() <= FAULT_EQUAL_TOLERANCE
            } else {
                dref == dt
            }
        }
        CompareOp::Notequal => {
            if faults.has(Fault::EqualWithTolerance) {
                let close = (dref - dt).abs() <= FAULT_EQUAL_TOLERANCE;
                !close
            } else if faults.has(Fault::NanOrderedNotequal) {
                // Ordered inequality: false when either operand is NaN.
                matches!(
                    dref.partial_cmp(&dt),
                    Some(std::cmp::Ordering::Less | std::cmp::Ordering::Greater)
                )
            } else {
                dref != dt
            }
        }
        CompareOp::TexelLeR => dt <= dref,
        CompareOp::TexelGeR => dt >= dref,
    }
}

/// The value a passing and a failing texel contribute (before filtering).
///
/// ARB_shadow_ambient: TEXTURE_COMPARE_FAIL_VALUE_ARB "replaces the 0.0" of a failing comparison
/// and is clamped to [0, 1] when set. SGIX_shadow_ambient's body: SHADOW_AMBIENT_SGIX is returned
/// "instead of 0.0" for a pixel "in shadow" (i.e. a failing test; the overview's "when the shadow
/// test passes" is the other reading, available as [`Fault::AmbientAppliedToPass`]). Other specs:
/// pass 1.0, fail 0.0; a `fail_value` set on them is ignored (the state does not exist there).
pub fn pass_fail_values(spec: Spec, fail_value: Option<f32>, faults: Faults) -> (f32, f32) {
    let ambient = match spec {
        Spec::SgixAmbient | Spec::ArbAmbient if faults.has(Fault::FailValueNotClamped) => {
            fail_value.unwrap_or(0.0)
        }
        Spec::SgixAmbient | Spec::ArbAmbient => crate::storage::clamp01(fail_value.unwrap_or(0.0)),
        _ => 0.0,
    };
    if faults.has(Fault::AmbientIgnored) {
        (1.0, 0.0)
    } else if faults.has(Fault::AmbientAppliedToPass)
        && matches!(spec, Spec::SgixAmbient | Spec::ArbAmbient)
    {
        (ambient, 0.0)
    } else {
        (1.0, ambient)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use CompareOp as O;
    const F: Faults = Faults::NONE;

    #[test]
    fn table_8_23_each_function() {
        // (op, Dref, Dt, expected) straight from Table 8.23.
        let rows = [
            (O::Lequal, 0.5, 0.5, true),
            (O::Lequal, 0.6, 0.5, false),
            (O::Gequal, 0.5, 0.5, true),
            (O::Gequal, 0.4, 0.5, false),
            (O::Less, 0.5, 0.5, false),
            (O::Less, 0.4, 0.5, true),
            (O::Greater, 0.5, 0.5, false),
            (O::Greater, 0.6, 0.5, true),
            (O::Equal, 0.5, 0.5, true),
            (O::Equal, 0.5, 0.25, false),
            (O::Notequal, 0.5, 0.5, false),
            (O::Notequal, 0.5, 0.25, true),
            (O::Always, 0.0, 1.0, true),
            (O::Never, 0.0, 1.0, false),
        ];
        for (op, r, d, want) in rows {
            assert_eq!(passes(op, r, d, F), want, "{op:?} Dref={r} Dt={d}");
        }
    }

    #[test]
    fn sgix_compares_texel_against_r() {
        // SGIX_shadow: LEQUAL_R passes if the texel value is <= R.
        let op = resolve_op(Spec::Sgix, CompareFunc::LequalRSgix, F).unwrap();
        assert!(passes(op, 0.75, 0.25, F)); // texel 0.25 <= R 0.75
        assert!(!passes(op, 0.25, 0.75, F));
        let op = resolve_op(Spec::Sgix, CompareFunc::GequalRSgix, F).unwrap();
        assert!(passes(op, 0.25, 0.75, F));
        assert!(!passes(op, 0.75, 0.25, F));
        // ARB's LEQUAL is the opposite: R <= Dt.
        let op = resolve_op(Spec::Arb, CompareFunc::Lequal, F).unwrap();
        assert!(!passes(op, 0.75, 0.25, F));
    }

    #[test]
    fn functions_each_spec_defines() {
        for f in CompareFunc::CORE {
            let arb_ok = matches!(f, CompareFunc::Lequal | CompareFunc::Gequal);
            assert_eq!(resolve_op(Spec::Arb, f, F).is_ok(), arb_ok, "{f}");
            assert_eq!(resolve_op(Spec::ArbAmbient, f, F).is_ok(), arb_ok, "{f}");
            assert!(resolve_op(Spec::Sgix, f, F).is_err(), "{f}");
            for s in [Spec::ExtFuncs, Spec::Es2Ext, Spec::Gl46, Spec::Gles32] {
                assert!(resolve_op(s, f, F).is_ok(), "{s} {f}");
            }
        }
        for s in [
            Spec::Arb,
            Spec::ExtFuncs,
            Spec::Es2Ext,
            Spec::Gl46,
            Spec::Gles32,
        ] {
            assert!(resolve_op(s, CompareFunc::LequalRSgix, F).is_err());
        }
    }

    #[test]
    fn webgpu_provided_value_against_sampled_value() {
        // WebGPU, Samplers: GPUSamplerDescriptor: "less": "A provided value passes the comparison test if it is less than
        // the sampled value": depth_ref 0.25 < texel 0.75 passes, depth_ref 0.75 does not.
        let op = resolve_op(Spec::WebGpu, CompareFunc::Less, F).unwrap();
        assert_eq!(op, O::Less);
        assert!(passes(op, 0.25, 0.75, F));
        assert!(!passes(op, 0.75, 0.25, F));
        let op = resolve_op(Spec::WebGpu, CompareFunc::Gequal, F).unwrap();
        assert!(passes(op, 0.75, 0.75, F) && !passes(op, 0.25, 0.75, F));
        for f in CompareFunc::CORE {
            assert!(resolve_op(Spec::WebGpu, f, F).is_ok(), "{f}");
        }
        assert!(resolve_op(Spec::WebGpu, CompareFunc::LequalRSgix, F).is_err());
        // The fault reads "texel OP depth_ref": LESS passes when the texel is the smaller.
        let swapped = F.with(Fault::WgpuCompareOperandsSwapped);
        let op = resolve_op(Spec::WebGpu, CompareFunc::Less, swapped).unwrap();
        assert!(passes(op, 0.75, 0.25, F));
        // No reference clamp for any WebGPU format (the literal reading).
        for fmt in [Format::D16, Format::D24, Format::D32f] {
            let none = ClampRule {
                dref: false,
                dt: false,
            };
            assert_eq!(clamp_rule(Spec::WebGpu, fmt, F), none);
        }
    }

    #[test]
    fn nan_reference() {
        // Every ordered comparison with NaN is false; NOTEQUAL (Dref != Dt) holds.
        for op in [O::Less, O::Lequal, O::Greater, O::Gequal, O::Equal] {
            assert!(!passes(op, f32::NAN, 0.5, F));
        }
        assert!(passes(O::Notequal, f32::NAN, 0.5, F));
        assert!(!passes(
            O::Notequal,
            f32::NAN,
            0.5,
            F.with(Fault::NanOrderedNotequal)
        ));
    }

    #[test]
    fn clamping_per_spec() {
        let both = ClampRule {
            dref: true,
            dt: true,
        };
        let none = ClampRule {
            dref: false,
            dt: false,
        };
        assert_eq!(clamp_rule(Spec::Gl46, Format::D24, F), both);
        assert_eq!(clamp_rule(Spec::Gl46, Format::D32f, F), none);
        assert_eq!(clamp_rule(Spec::Gles32, Format::D32fS8, F), none);
        assert_eq!(clamp_rule(Spec::Es2Ext, Format::D32f, F), both);
        assert_eq!(clamp_rule(Spec::Arb, Format::D16, F), both);
        assert_eq!(clamp_rule(Spec::Sgix, Format::D16, F), both);
        assert!(clamp_rule(Spec::Gl46, Format::D32f, F.with(Fault::RefClampedForFloat)).dref);
    }

    #[test]
    fn fail_values() {
        assert_eq!(
            pass_fail_values(Spec::ArbAmbient, Some(0.25), F),
            (1.0, 0.25)
        );
        assert_eq!(
            pass_fail_values(Spec::SgixAmbient, Some(1.5), F),
            (1.0, 1.0)
        ); // clamped when set
        assert_eq!(pass_fail_values(Spec::SgixAmbient, None, F), (1.0, 0.0)); // initial 0.0
        assert_eq!(pass_fail_values(Spec::Gl46, Some(0.25), F), (1.0, 0.0));
        assert_eq!(
            pass_fail_values(
                Spec::ArbAmbient,
                Some(0.25),
                F.with(Fault::AmbientAppliedToPass)
            ),
            (0.25, 0.0)
        );
    }

    #[test]
    fn faults_swap_functions() {
        let s = F.with(Fault::LequalGequalSwapped);
        assert_eq!(
            resolve_op(Spec::Gl46, CompareFunc::Lequal, s).unwrap(),
            O::Gequal
        );
        assert_eq!(
            resolve_op(Spec::Gl46, CompareFunc::Less, F.with(Fault::LessAsLequal)).unwrap(),
            O::Lequal
        );
        assert!(passes(
            O::Equal,
            0.5,
            0.5001,
            F.with(Fault::EqualWithTolerance)
        ));
    }
}
