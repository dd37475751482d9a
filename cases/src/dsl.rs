//! A small, typed grid DSL: a cartesian product of named dimensions over a parameter struct, with
//! filters that prune the combinations a specification forbids (each filter says why) and values
//! derived from earlier ones. In the spirit of the WebGPU CTS `.combine(...).filter(...)` builder,
//! but over a plain Rust struct instead of untyped records:
//!
//! ```
//! use shadowcheck_cases::dsl::Grid;
//! #[derive(Clone, Debug, PartialEq)]
//! struct P { a: u32, b: u32, sum: u32 }
//! let g = Grid::new("demo", [P { a: 0, b: 0, sum: 0 }])
//!     .combine("a", [1, 2, 3], |p, v| p.a = v)
//!     .combine_with("b", |p| (0..p.a).collect::<Vec<_>>(), |p, v| p.b = v)
//!     .filter("b must be even", |p| p.b % 2 == 0)
//!     .derive(|p| p.sum = p.a + p.b);
//! assert_eq!(g.len(), 4); // (1,0) (2,0) (3,0) (3,2)
//! assert_eq!(g.pruned(), &[("b must be even".to_string(), 2)]);
//! ```
//!
//! The order of the items is the order of the product (first dimension slowest), so a grid built
//! from the same calls always yields the same sequence: fixtures are deterministic by construction.

/// A list of parameter combinations under construction.
#[derive(Debug, Clone)]
pub struct Grid<P> {
    name: String,
    items: Vec<P>,
    dims: Vec<String>,
    pruned: Vec<(String, usize)>,
}

impl<P: Clone> Grid<P> {
    /// Starts a grid from seed items (usually one struct holding default values).
    pub fn new(name: impl Into<String>, seed: impl IntoIterator<Item = P>) -> Grid<P> {
        Grid {
            name: name.into(),
            items: seed.into_iter().collect(),
            dims: Vec::new(),
            pruned: Vec::new(),
        }
    }

    /// Crosses every item with every value of a dimension; `set` writes the value into the item.
    pub fn combine<V: Clone>(
        self,
        dim: &str,
        values: impl IntoIterator<Item = V>,
        set: impl Fn(&mut P, V),
    ) -> Grid<P> {
        let values: Vec<V> = values.into_iter().collect();
        self.combine_with(dim, |_| values.clone(), set)
    }

    /// Like [`Grid::combine`], but the values of the dimension depend on the item so far (e.g. the
    /// compare functions a spec defines, the formats a target allows).
    pub fn combine_with<V, I: IntoIterator<Item = V>>(
        mut self,
        dim: &str,
        values: impl Fn(&P) -> I,
        set: impl Fn(&mut P, V),
    ) -> Grid<P> {
        let mut out = Vec::with_capacity(self.items.len());
        for item in &self.items {
            for v in values(item) {
                let mut next = item.clone();
                set(&mut next, v);
                out.push(next);
            }
        }
        self.items = out;
        self.dims.push(dim.to_string());
        self
    }

    /// Keeps the items for which `keep` is true. `why` says which rule removes the others (a spec
    /// citation where the rule comes from a spec); the counts are kept for the generator's report.
    pub fn filter(mut self, why: &str, keep: impl Fn(&P) -> bool) -> Grid<P> {
        let before = self.items.len();
        self.items.retain(|p| keep(p));
        let removed = before - self.items.len();
        if let Some(slot) = self.pruned.iter_mut().find(|(w, _)| w == why) {
            slot.1 += removed;
        } else {
            self.pruned.push((why.to_string(), removed));
        }
        self
    }

    /// Sets values derived from the dimensions chosen so far.
    pub fn derive(mut self, f: impl Fn(&mut P)) -> Grid<P> {
        for p in &mut self.items {
            f(p);
        }
        self
    }

    /// Expands each item into any number of items (e.g. one parameter set into its lookups).
    pub fn flat_map<Q: Clone, I: IntoIterator<Item = Q>>(self, f: impl Fn(&P) -> I) -> Grid<Q> {
        Grid {
            name: self.name,
            items: self.items.iter().flat_map(f).collect(),
            dims: self.dims,
            pruned: self.pruned,
        }
    }

    /// Appends items built elsewhere (e.g. a focused family) so later filters see them too.
    pub fn extend(mut self, items: impl IntoIterator<Item = P>) -> Grid<P> {
        self.items.extend(items);
        self
    }

    pub fn name(&self) -> &str {
        &self.name
    }
    /// The dimension names, in the order they were combined.
    pub fn dims(&self) -> &[String] {
        &self.dims
    }
    /// (reason, number of combinations removed) per filter, in the order the filters ran.
    pub fn pruned(&self) -> &[(String, usize)] {
        &self.pruned
    }
    pub fn len(&self) -> usize {
        self.items.len()
    }
    pub fn is_empty(&self) -> bool {
        self.items.is_empty()
    }
    pub fn items(&self) -> &[P] {
        &self.items
    }
    pub fn into_items(self) -> Vec<P> {
        self.items
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn product_order_is_first_dimension_slowest() {
        let g = Grid::new("t", [(0u8, 'x')])
            .combine("n", [1u8, 2], |p, v| p.0 = v)
            .combine("c", ['a', 'b'], |p, v| p.1 = v);
        assert_eq!(g.items(), &[(1, 'a'), (1, 'b'), (2, 'a'), (2, 'b')]);
        assert_eq!(g.dims(), &["n".to_string(), "c".to_string()]);
    }

    #[test]
    fn filters_accumulate_counts_by_reason() {
        let g = Grid::new("t", [0u32])
            .combine("n", 0..10, |p, v| *p = v)
            .filter("odd", |p| p % 2 == 0)
            .filter("big", |p| *p < 6)
            .filter("odd", |p| *p != 0);
        assert_eq!(g.items(), &[2, 4]);
        assert_eq!(
            g.pruned(),
            &[("odd".to_string(), 6), ("big".to_string(), 2)]
        );
    }

    #[test]
    fn dependent_dimensions_and_flat_map() {
        let g = Grid::new("t", [(0u32, 0u32)])
            .combine("a", 1..=3, |p, v| p.0 = v)
            .combine_with("b", |p| 0..p.0, |p, v| p.1 = v)
            .flat_map(|p| [p.0 * 10 + p.1]);
        assert_eq!(g.items(), &[10, 20, 21, 30, 31, 32]);
    }
}
