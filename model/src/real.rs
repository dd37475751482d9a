//! JSON has no NaN or infinity. Values that may be non-finite (the reference value, coordinates)
//! are written as numbers when finite and as the strings "nan", "inf", "-inf" otherwise.

use serde::{de, Deserializer, Serializer};

pub fn serialize<S: Serializer>(v: &f64, s: S) -> Result<S::Ok, S::Error> {
    if v.is_nan() {
        s.serialize_str("nan")
    } else if v.is_infinite() {
        s.serialize_str(if *v > 0.0 { "inf" } else { "-inf" })
    } else {
        s.serialize_f64(*v)
    }
}

pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    d.deserialize_any(RealVisitor)
}

pub(crate) struct RealVisitor;

impl de::Visitor<'_> for RealVisitor {
    type Value = f64;
    fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
        f.write_str("a number or one of \"nan\", \"inf\", \"-inf\"")
    }
    fn visit_f64<E: de::Error>(self, v: f64) -> Result<f64, E> {
        Ok(v)
    }
    fn visit_i64<E: de::Error>(self, v: i64) -> Result<f64, E> {
        Ok(v as f64)
    }
    fn visit_u64<E: de::Error>(self, v: u64) -> Result<f64, E> {
        Ok(v as f64)
    }
    fn visit_str<E: de::Error>(self, v: &str) -> Result<f64, E> {
        match v {
            "nan" => Ok(f64::NAN),
            "inf" => Ok(f64::INFINITY),
            "-inf" => Ok(f64::NEG_INFINITY),
            _ => Err(E::invalid_value(de::Unexpected::Str(v), &self)),
        }
    }
}

/// The same encoding for fixed-size arrays of reals (coordinates).
pub mod array4 {
    use serde::ser::SerializeTuple;
    use serde::{de, Deserializer, Serializer};

    struct W(f64);
    impl serde::Serialize for W {
        fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
            super::serialize(&self.0, s)
        }
    }

    pub fn serialize<S: Serializer>(v: &[f64; 4], s: S) -> Result<S::Ok, S::Error> {
        let mut t = s.serialize_tuple(4)?;
        for x in v {
            t.serialize_element(&W(*x))?;
        }
        t.end()
    }

    pub fn deserialize<'de, D: Deserializer<'de>>(d: D) -> Result<[f64; 4], D::Error> {
        struct R(f64);
        impl<'de> serde::Deserialize<'de> for R {
            fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
                d.deserialize_any(super::RealVisitor).map(R)
            }
        }
        struct V;
        impl<'de> de::Visitor<'de> for V {
            type Value = [f64; 4];
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("an array of 4 reals")
            }
            fn visit_seq<A: de::SeqAccess<'de>>(self, mut a: A) -> Result<[f64; 4], A::Error> {
                let mut out = [0.0; 4];
                for (i, slot) in out.iter_mut().enumerate() {
                    *slot = a
                        .next_element::<R>()?
                        .ok_or_else(|| de::Error::invalid_length(i, &self))?
                        .0;
                }
                if a.next_element::<R>()?.is_some() {
                    return Err(de::Error::invalid_length(5, &self));
                }
                Ok(out)
            }
        }
        d.deserialize_tuple(4, V)
    }
}
