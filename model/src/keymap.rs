//! [`KeyMap`]: a map keyed by one of the model's keyed enums (API path, profile), stored flat: one
//! slot per enum value, found by the value's position, with no tree to walk. The verdict path looks
//! up a layout and an acceptance set per observation; this keeps that a bounds-checked index.
//!
//! It reads and writes as a JSON object exactly as the `BTreeMap` it replaces did (the keys in
//! declaration order, which is the enums' `Ord` order), so fixtures are unchanged.

use serde::de::{Deserialize, Deserializer, MapAccess, Visitor};
use serde::ser::{Serialize, SerializeMap, Serializer};
use std::fmt;
use std::marker::PhantomData;

/// A keyed enum: fieldless, its values listed in declaration order.
pub trait Keyed: Copy + Ord + 'static {
    const ALL: &'static [Self];
    /// Position in [`Keyed::ALL`].
    fn index(self) -> usize;
}

/// A map from a [`Keyed`] enum to `V`, one slot per key.
#[derive(Clone, PartialEq)]
pub struct KeyMap<K: Keyed, V> {
    slots: Vec<Option<V>>,
    _key: PhantomData<K>,
}

impl<K: Keyed, V> KeyMap<K, V> {
    pub fn new() -> Self {
        KeyMap {
            slots: K::ALL.iter().map(|_| None).collect(),
            _key: PhantomData,
        }
    }
    pub fn get(&self, k: &K) -> Option<&V> {
        self.slots.get(k.index())?.as_ref()
    }
    pub fn get_mut(&mut self, k: &K) -> Option<&mut V> {
        self.slots.get_mut(k.index())?.as_mut()
    }
    /// Sets `k`, returning its old value.
    pub fn insert(&mut self, k: K, v: V) -> Option<V> {
        self.slots.get_mut(k.index())?.replace(v)
    }
    pub fn remove(&mut self, k: &K) -> Option<V> {
        self.slots.get_mut(k.index())?.take()
    }
    pub fn contains_key(&self, k: &K) -> bool {
        self.get(k).is_some()
    }
    pub fn len(&self) -> usize {
        self.slots.iter().filter(|s| s.is_some()).count()
    }
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// The entries in key order.
    pub fn iter(&self) -> impl Iterator<Item = (&K, &V)> + '_ {
        K::ALL
            .iter()
            .zip(&self.slots)
            .filter_map(|(k, s)| s.as_ref().map(|v| (k, v)))
    }
    pub fn keys(&self) -> impl Iterator<Item = &K> + '_ {
        self.iter().map(|(k, _)| k)
    }
    pub fn values(&self) -> impl Iterator<Item = &V> + '_ {
        self.iter().map(|(_, v)| v)
    }
}

impl<K: Keyed, V> Default for KeyMap<K, V> {
    fn default() -> Self {
        KeyMap::new()
    }
}

impl<K: Keyed + fmt::Debug, V: fmt::Debug> fmt::Debug for KeyMap<K, V> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_map().entries(self.iter()).finish()
    }
}

impl<K: Keyed, V> FromIterator<(K, V)> for KeyMap<K, V> {
    fn from_iter<I: IntoIterator<Item = (K, V)>>(iter: I) -> Self {
        let mut m = KeyMap::new();
        for (k, v) in iter {
            m.insert(k, v);
        }
        m
    }
}

impl<K: Keyed, V, const N: usize> From<[(K, V); N]> for KeyMap<K, V> {
    fn from(entries: [(K, V); N]) -> Self {
        entries.into_iter().collect()
    }
}

/// `map[&k]`, as `BTreeMap` indexes: panics when `k` has no value (for tests and tables whose
/// keys are known; look-ups of input use [`KeyMap::get`]).
impl<K: Keyed, V> std::ops::Index<&K> for KeyMap<K, V> {
    type Output = V;
    fn index(&self, k: &K) -> &V {
        match self.get(k) {
            Some(v) => v,
            None => panic!("KeyMap: no value for key #{}", k.index()),
        }
    }
}

impl<'a, K: Keyed, V> IntoIterator for &'a KeyMap<K, V> {
    type Item = (&'a K, &'a V);
    type IntoIter = Box<dyn Iterator<Item = (&'a K, &'a V)> + 'a>;
    fn into_iter(self) -> Self::IntoIter {
        Box::new(self.iter())
    }
}

impl<K: Keyed + Serialize, V: Serialize> Serialize for KeyMap<K, V> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut m = s.serialize_map(Some(self.len()))?;
        for (k, v) in self.iter() {
            m.serialize_entry(k, v)?;
        }
        m.end()
    }
}

impl<'de, K, V> Deserialize<'de> for KeyMap<K, V>
where
    K: Keyed + Deserialize<'de>,
    V: Deserialize<'de>,
{
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V2<K, V>(PhantomData<(K, V)>);
        impl<'de, K: Keyed + Deserialize<'de>, V: Deserialize<'de>> Visitor<'de> for V2<K, V> {
            type Value = KeyMap<K, V>;
            fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
                f.write_str("a map")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut a: A) -> Result<Self::Value, A::Error> {
                let mut m = KeyMap::new();
                while let Some((k, v)) = a.next_entry::<K, V>()? {
                    m.insert(k, v);
                }
                Ok(m)
            }
        }
        d.deserialize_map(V2(PhantomData))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{ApiPath, Profile};
    use std::collections::BTreeMap;

    #[test]
    fn reads_and_writes_as_the_btreemap_it_replaces() {
        let tree: BTreeMap<ApiPath, u8> = [(ApiPath::Es300, 3), (ApiPath::FixedFunction, 1)].into();
        let flat: KeyMap<ApiPath, u8> = [(ApiPath::Es300, 3), (ApiPath::FixedFunction, 1)].into();
        let text = serde_json::to_string(&tree).unwrap();
        assert_eq!(serde_json::to_string(&flat).unwrap(), text);
        let back: KeyMap<ApiPath, u8> = serde_json::from_str(&text).unwrap();
        assert_eq!(back, flat);
        assert_eq!(back.len(), 2);
        assert_eq!(back.get(&ApiPath::Es300), Some(&3));
        assert_eq!(back.get(&ApiPath::GlslCore), None);
        let keys: Vec<_> = back.keys().copied().collect();
        assert_eq!(keys, tree.keys().copied().collect::<Vec<_>>());
        let bad: Result<KeyMap<Profile, u8>, _> = serde_json::from_str(r#"{"nope":1}"#);
        assert!(bad.is_err());
    }

    #[test]
    fn insert_and_remove_return_the_old_value() {
        let mut m: KeyMap<Profile, &str> = KeyMap::new();
        assert!(m.is_empty());
        assert_eq!(m.insert(Profile::ALL[0], "a"), None);
        assert_eq!(m.insert(Profile::ALL[0], "b"), Some("a"));
        assert_eq!(m.remove(&Profile::ALL[0]), Some("b"));
        assert!(!m.contains_key(&Profile::ALL[0]));
    }
}
