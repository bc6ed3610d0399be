//! [`SCHEMA_HASH`]: a 64-bit fingerprint of every type on the wire, computed
//! at compile time from the types' `postcard_schema::Schema` derivations.
//!
//! The hash covers the names and shapes of all types, fields and variants of
//! [`Request`] and [`DeviceMessage`] (FNV-1a, 64 bit), plus the capacities that
//! the schema itself does not carry ([`MAX_SEGMENTS`], [`MAX_PARAMS`],
//! [`MAX_FRAME_LEN`]). Any change to the wire therefore changes the hash,
//! without anyone having to remember to bump a number. Renaming a field also
//! changes it: deliberately conservative.

use postcard_schema::schema::{
    DataModelType, DataModelVariant, NamedType, NamedValue, NamedVariant,
};
use postcard_schema::Schema;

use crate::frame::MAX_FRAME_LEN;
use crate::message::{DeviceMessage, Request};
use crate::params::MAX_PARAMS;
use crate::profile::MAX_SEGMENTS;

/// Fingerprint of the wire schema of this build; exchanged in the handshake.
pub const SCHEMA_HASH: u64 = {
    let mut h = FNV_OFFSET;
    h = named_type(h, Request::SCHEMA);
    h = named_type(h, DeviceMessage::SCHEMA);
    h = number(h, MAX_SEGMENTS as u64);
    h = number(h, MAX_PARAMS as u64);
    number(h, MAX_FRAME_LEN as u64)
};

const FNV_OFFSET: u64 = 0xcbf2_9ce4_8422_2325;
const FNV_PRIME: u64 = 0x0000_0100_0000_01b3;

const fn byte(h: u64, b: u8) -> u64 {
    (h ^ b as u64).wrapping_mul(FNV_PRIME)
}

const fn bytes(mut h: u64, s: &[u8]) -> u64 {
    let mut i = 0;
    while i < s.len() {
        h = byte(h, s[i]);
        i += 1;
    }
    // A terminator, so that ("ab", "c") and ("a", "bc") differ.
    byte(h, 0xff)
}

const fn number(h: u64, n: u64) -> u64 {
    bytes(h, &n.to_le_bytes())
}

const fn named_type(h: u64, t: &NamedType) -> u64 {
    data_model_type(bytes(h, t.name.as_bytes()), t.ty)
}

const fn named_types(mut h: u64, ts: &[&NamedType]) -> u64 {
    h = number(h, ts.len() as u64);
    let mut i = 0;
    while i < ts.len() {
        h = named_type(h, ts[i]);
        i += 1;
    }
    h
}

const fn named_values(mut h: u64, vs: &[&NamedValue]) -> u64 {
    h = number(h, vs.len() as u64);
    let mut i = 0;
    while i < vs.len() {
        h = bytes(h, vs[i].name.as_bytes());
        h = named_type(h, vs[i].ty);
        i += 1;
    }
    h
}

const fn named_variants(mut h: u64, vs: &[&NamedVariant]) -> u64 {
    h = number(h, vs.len() as u64);
    let mut i = 0;
    while i < vs.len() {
        h = bytes(h, vs[i].name.as_bytes());
        h = match vs[i].ty {
            DataModelVariant::UnitVariant => byte(h, 0),
            DataModelVariant::NewtypeVariant(t) => named_type(byte(h, 1), t),
            DataModelVariant::TupleVariant(ts) => named_types(byte(h, 2), ts),
            DataModelVariant::StructVariant(vs) => named_values(byte(h, 3), vs),
        };
        i += 1;
    }
    h
}

const fn data_model_type(h: u64, t: &DataModelType) -> u64 {
    use DataModelType as D;
    match t {
        D::Bool => byte(h, 1),
        D::I8 => byte(h, 2),
        D::U8 => byte(h, 3),
        D::I16 => byte(h, 4),
        D::I32 => byte(h, 5),
        D::I64 => byte(h, 6),
        D::I128 => byte(h, 7),
        D::U16 => byte(h, 8),
        D::U32 => byte(h, 9),
        D::U64 => byte(h, 10),
        D::U128 => byte(h, 11),
        D::Usize => byte(h, 12),
        D::Isize => byte(h, 13),
        D::F32 => byte(h, 14),
        D::F64 => byte(h, 15),
        D::Char => byte(h, 16),
        D::String => byte(h, 17),
        D::ByteArray => byte(h, 18),
        D::Option(t) => named_type(byte(h, 19), t),
        D::Unit => byte(h, 20),
        D::UnitStruct => byte(h, 21),
        D::NewtypeStruct(t) => named_type(byte(h, 22), t),
        D::Seq(t) => named_type(byte(h, 23), t),
        D::Tuple(ts) => named_types(byte(h, 24), ts),
        D::TupleStruct(ts) => named_types(byte(h, 25), ts),
        D::Map { key, val } => named_type(named_type(byte(h, 26), key), val),
        D::Struct(vs) => named_values(byte(h, 27), vs),
        D::Enum(vs) => named_variants(byte(h, 28), vs),
        D::Schema => byte(h, 29),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde::{Deserialize, Serialize};

    #[allow(dead_code)]
    #[derive(Serialize, Deserialize, Schema)]
    struct A {
        x: f32,
        y: u16,
    }
    #[allow(dead_code)]
    #[derive(Serialize, Deserialize, Schema)]
    struct B {
        x: f32,
        y: u32, // one field's width differs from A
    }
    #[allow(dead_code)]
    #[derive(Serialize, Deserialize, Schema)]
    enum E1 {
        P,
        Q(u8),
    }
    #[allow(dead_code)]
    #[derive(Serialize, Deserialize, Schema)]
    enum E2 {
        Q(u8),
        P,
    }

    #[test]
    fn hash_sees_field_type_and_variant_order() {
        let a = named_type(FNV_OFFSET, A::SCHEMA);
        let b = named_type(FNV_OFFSET, B::SCHEMA);
        assert_ne!(a, b);
        let e1 = data_model_type(FNV_OFFSET, E1::SCHEMA.ty);
        let e2 = data_model_type(FNV_OFFSET, E2::SCHEMA.ty);
        assert_ne!(e1, e2, "reordering variants must change the hash");
    }

    #[test]
    fn fnv1a_matches_published_test_vector() {
        // FNV-1a 64 of "a" is 0xaf63dc4c8601ec8c (Fowler/Noll/Vo test suite).
        assert_eq!(byte(FNV_OFFSET, b'a'), 0xaf63_dc4c_8601_ec8c);
    }
}
