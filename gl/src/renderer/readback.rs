//! The result framebuffer of a batch: an RGBA32F colour buffer of 2x2 pixel quads, one per (case,
//! API path), whose lower-left pixel holds the result ("slots", taken in order and read back
//! together). A pixel no draw wrote reads back as -1, which no path can return.

use super::{BatchState, Pending, Renderer};
use glow::HasContext;
use shadowcheck_plan::layout::pixel;
use shadowcheck_plan::layout::{CAPACITY, FB_SIZE, QUADS_PER_ROW};
use shadowcheck_protocol::{PathResult, Rgba};

impl Renderer {
    /// Reads the framebuffer's pixels up to the quad row of slot `used - 1`, row by row, into
    /// `self.readback` (RGBA32F, 16 bytes a pixel; the buffer is kept from batch to batch).
    pub(crate) unsafe fn read(&mut self, used: usize) {
        let rows = 2 * used.div_ceil(QUADS_PER_ROW as usize).max(1) as i32;
        self.readback.clear();
        self.readback.resize((FB_SIZE * rows) as usize * 16, 0);
        self.gl
            .bind_framebuffer(glow::READ_FRAMEBUFFER, Some(self.fbo));
        self.gl.read_pixels(
            0,
            0,
            FB_SIZE,
            rows,
            glow::RGBA,
            glow::FLOAT,
            glow::PixelPackData::Slice(Some(&mut self.readback)),
        );
    }

    /// Pixel (x, y) of the last [`Renderer::read`], or NaN where it was not read.
    fn read_pixel(&self, x: i32, y: i32) -> [f32; 4] {
        let at = (y * FB_SIZE + x) as usize * 16;
        match self.readback.get(at..at + 16) {
            Some(c) => {
                let f = |i: usize| f32::from_ne_bytes([c[i], c[i + 1], c[i + 2], c[i + 3]]);
                [f(0), f(4), f(8), f(12)]
            }
            None => [f32::NAN; 4],
        }
    }

    /// Clears the quad rows drawn since the last clear (only those: clearing the whole
    /// framebuffer before every batch cost llvmpipe a 1 MiB fill per batch).
    pub(crate) unsafe fn clear(&mut self) {
        let rows = (2 * self.drawn.div_ceil(QUADS_PER_ROW as usize)).min(FB_SIZE as usize) as i32;
        self.drawn = 0;
        self.gl.bind_framebuffer(glow::FRAMEBUFFER, Some(self.fbo));
        self.gl.viewport(0, 0, FB_SIZE, FB_SIZE);
        if rows == 0 {
            return;
        }
        // A pixel no draw wrote reads back as -1, which no path can return.
        self.gl.clear_color(-1.0, -1.0, -1.0, -1.0);
        self.gl.enable(glow::SCISSOR_TEST);
        self.gl.scissor(0, 0, FB_SIZE, rows);
        self.gl.clear(glow::COLOR_BUFFER_BIT);
        self.gl.disable(glow::SCISSOR_TEST);
    }

    /// Takes `n` consecutive slots, reading back and clearing first when the framebuffer cannot
    /// hold them; returns the first.
    pub(crate) unsafe fn take_slots(&mut self, st: &mut BatchState, n: usize) -> usize {
        if st.next_slot + n > CAPACITY {
            let mut pending = std::mem::take(&mut st.pending);
            self.collect(&mut pending, &mut st.results);
            self.clear();
            st.next_slot = 0;
        }
        let first = st.next_slot;
        st.next_slot += n;
        self.drawn = self.drawn.max(st.next_slot);
        first
    }

    /// Reads back the pending pixels into `results`.
    pub(crate) unsafe fn collect(
        &mut self,
        pending: &mut Vec<Pending>,
        results: &mut [Vec<PathResult>],
    ) {
        if pending.is_empty() {
            return;
        }
        let used = pending.iter().map(|p| p.slot + 1).max().unwrap_or(1);
        self.read(used);
        for p in pending.drain(..) {
            let (x, y) = pixel(p.slot);
            let v = self.read_pixel(x, y);
            results[p.case].push(PathResult {
                sweep: vec![],
                api: p.path.key().to_string(),
                rgba: Rgba(v.map(|c| c as f64)),
                stored: None,
                note: Some(p.note),
            });
        }
    }
}
