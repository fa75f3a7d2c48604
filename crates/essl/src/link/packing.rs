//! Packing variables into rows of four components, as GLSL ES 1.00 Appendix A §7 describes it
//! and ANGLE implements it for varyings of both language versions (`VaryingPacking`, WebGL's
//! strict mode): WebGL fails a program whose varyings do not pack into `MAX_VARYING_VECTORS`
//! rows (WebGL 1.0 "Packing Restrictions for Uniforms and Varyings"), and guarantees that those
//! which pack into its minimum work everywhere.
//!
//! Each variable (a struct split into its fields) occupies a rectangle: as many rows as it has
//! vectors (a `matCxR` has C, an array N times its element's), as many columns as a vector has
//! components; a `mat2` takes whole rows. They are placed largest class first (4-column types,
//! then `mat2`, 3-column, 2-column, single components; larger arrays first within a class):
//! 2- to 4-column variables in the first free rows from the left, a 2-column one in the right
//! half from the bottom when the left is full, single components in the column that leaves the
//! least space.

use crate::source::Span;
use crate::types::{StructDef, Type};

/// A variable to pack: its rectangle and its rank in the packing order.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) struct PackItem {
    /// Components per row (1 to 4).
    pub columns: u32,
    /// Rows (array elements included).
    pub rows: u32,
    /// Appendix A's order of types: 0 (4-row matrices) to 6 (single components).
    order: u8,
    /// The array length (larger arrays are packed first within an order).
    array: u32,
    /// The variable's (or field's) name, for messages.
    pub name: String,
    /// Where the variable is declared.
    pub span: Span,
}

/// The rectangles of a variable named `name` of type `ty`: one, or one per field of a struct
/// (per element of an array of structs).
pub(crate) fn items_of(name: &str, ty: &Type, structs: &[StructDef], span: Span) -> Vec<PackItem> {
    let mut out = Vec::new();
    expand(name, ty, structs, &mut out);
    for i in &mut out {
        i.span = span;
    }
    out
}

fn expand(name: &str, ty: &Type, structs: &[StructDef], out: &mut Vec<PackItem>) {
    let (el, n) = match ty {
        Type::Array(el, n) => (&**el, *n),
        t => (t, 1),
    };
    if let Type::Struct(id) = el {
        let Some(s) = structs.get(id.0 as usize) else {
            return;
        };
        for i in 0..n {
            let base = if matches!(ty, Type::Array(..)) {
                format!("{name}[{i}]")
            } else {
                name.to_string()
            };
            for m in &s.members {
                expand(&format!("{base}.{}", m.name), &m.ty, structs, out);
            }
        }
        return;
    }
    let (columns, rows, order) = match el {
        Type::Matrix { cols: 2, rows: 2 } => (4, 2, 1),
        Type::Matrix { cols, rows } if *cols == 4 || *rows == 4 => {
            (u32::from(*rows), u32::from(*cols), 0)
        }
        Type::Matrix { cols, rows } => (u32::from(*rows), u32::from(*cols), 3),
        Type::Vector(_, 4) => (4, 1, 2),
        Type::Vector(_, 3) => (3, 1, 4),
        Type::Vector(_, _) => (2, 1, 5),
        _ => (1, 1, 6),
    };
    out.push(PackItem {
        columns,
        rows: rows.saturating_mul(n),
        order,
        array: n,
        name: name.to_string(),
        span: Span::default(),
    });
}

/// Packs `items` into `max_rows` rows; the first that does not fit, if any.
///
/// Items whose rows add up to no more than `max_rows` always fit, each in rows of its own (the
/// 2- to 4-column ones fill rows from the top, single components then find a free run below
/// them), so only a program with more needs the grid: most have a handful of uniforms against
/// hundreds of rows.
pub(crate) fn pack(items: &[PackItem], max_rows: u32) -> Result<(), &PackItem> {
    let rows: u64 = items.iter().map(|i| u64::from(i.rows)).sum();
    if rows <= u64::from(max_rows) {
        return Ok(());
    }
    pack_in_grid(items, max_rows)
}

/// [`pack`] by placing every item in a grid.
fn pack_in_grid(items: &[PackItem], max_rows: u32) -> Result<(), &PackItem> {
    let mut sorted: Vec<&PackItem> = items.iter().collect();
    sorted.sort_by_key(|i| (i.order, std::cmp::Reverse(i.array)));
    let mut grid = Grid {
        rows: vec![[false; 4]; max_rows as usize],
    };
    for item in sorted {
        if !grid.place(item) {
            return Err(item);
        }
    }
    Ok(())
}

/// Which of the four components of each row are taken.
struct Grid {
    rows: Vec<[bool; 4]>,
}

impl Grid {
    fn free(&self, row: usize, column: usize, rows: usize, columns: usize) -> bool {
        (row..row + rows).all(|r| (column..column + columns).all(|c| !self.rows[r][c]))
    }

    fn fill(&mut self, row: usize, column: usize, rows: usize, columns: usize) {
        for r in row..row + rows {
            for c in column..column + columns {
                self.rows[r][c] = true;
            }
        }
    }

    /// Places one variable; whether it fits.
    fn place(&mut self, item: &PackItem) -> bool {
        let max = self.rows.len();
        let (rows, columns) = (item.rows as usize, item.columns as usize);
        if rows > max {
            return false;
        }
        if columns >= 2 {
            if let Some(r) = (0..=max - rows).find(|&r| self.free(r, 0, rows, columns)) {
                self.fill(r, 0, rows, columns);
                return true;
            }
            if columns == 2 {
                if let Some(r) = (0..=max - rows).rev().find(|&r| self.free(r, 2, rows, 2)) {
                    self.fill(r, 2, rows, 2);
                    return true;
                }
            }
            return false;
        }
        // One component: the column with room for it that has the least free space.
        let mut best: Option<(usize, usize)> = None; // (column, total free)
        for c in 0..4 {
            let (mut run, mut longest, mut total) = (0, 0, 0);
            for r in 0..max {
                if self.rows[r][c] {
                    run = 0;
                } else {
                    run += 1;
                    total += 1;
                    longest = longest.max(run);
                }
            }
            if longest >= rows && best.is_none_or(|(_, t)| total < t) {
                best = Some((c, total));
            }
        }
        let Some((c, _)) = best else {
            return false;
        };
        match (0..=max - rows).find(|&r| self.free(r, c, rows, 1)) {
            Some(r) => {
                self.fill(r, c, rows, 1);
                true
            }
            None => false,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::types::ScalarKind::Float;

    fn n_of(ty: Type, n: usize) -> Vec<PackItem> {
        (0..n)
            .flat_map(|i| items_of(&format!("v{i}"), &ty, &[], Span::default()))
            .collect()
    }

    #[test]
    fn two_component_vectors_share_rows() {
        // 16 separate vec2 fit in 8 rows (two per row), which a vector per varying would not.
        assert!(pack(&n_of(Type::Vector(Float, 2), 16), 8).is_ok());
        assert!(pack(&n_of(Type::Vector(Float, 2), 17), 8).is_err());
        assert!(pack(&n_of(Type::Vector(Float, 2), 62), 31).is_ok());
    }

    #[test]
    fn single_components_fill_columns() {
        assert!(pack(&n_of(Type::FLOAT, 124), 31).is_ok());
        assert!(pack(&n_of(Type::FLOAT, 125), 31).is_err());
        // An array stays in one column.
        assert!(pack(
            &items_of(
                "a",
                &Type::Array(Box::new(Type::FLOAT), 32),
                &[],
                Span::default()
            ),
            31
        )
        .is_err());
    }

    proptest::proptest! {
        /// The shortcut: items that fit in rows of their own always pack in the grid too.
        #[test]
        fn items_in_rows_of_their_own_always_pack(
            kinds in proptest::collection::vec((0usize..8, 1u32..4), 0..24),
            spare in 0u32..4,
        ) {
            let types = [
                Type::FLOAT,
                Type::Vector(Float, 2),
                Type::Vector(Float, 3),
                Type::Vector(Float, 4),
                Type::Matrix { cols: 2, rows: 2 },
                Type::Matrix { cols: 3, rows: 3 },
                Type::Matrix { cols: 4, rows: 4 },
                Type::Matrix { cols: 2, rows: 4 },
            ];
            let items: Vec<PackItem> = kinds
                .iter()
                .enumerate()
                .flat_map(|(i, &(k, n))| {
                    let ty = if n == 1 {
                        types[k].clone()
                    } else {
                        Type::Array(Box::new(types[k].clone()), n)
                    };
                    items_of(&format!("v{i}"), &ty, &[], Span::default())
                })
                .collect();
            let rows: u32 = items.iter().map(|i| i.rows).sum();
            proptest::prop_assert!(pack_in_grid(&items, rows + spare).is_ok());
        }
    }

    #[test]
    fn mat2_takes_whole_rows() {
        let m2 = Type::Matrix { cols: 2, rows: 2 };
        assert!(pack(&n_of(m2.clone(), 15), 31).is_ok());
        assert!(pack(&n_of(m2, 16), 31).is_err());
    }
}
