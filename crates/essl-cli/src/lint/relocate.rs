//! Moving diagnostics from a shader's own text onto the file that holds it: every span (the
//! primary one, the secondary labels', the fix's edits) shifted by the shader's offset there.

use essl::diagnostic::Diagnostic;
use essl::source::Span;

/// Shifts every span of `diagnostics` by `by` bytes.
pub(crate) fn relocate(diagnostics: &mut [Diagnostic], by: u32) {
    let shift = |s: &mut Span| {
        s.start += by;
        s.end += by;
    };
    for d in diagnostics {
        shift(&mut d.span);
        for label in &mut d.secondary {
            shift(&mut label.span);
        }
        if let Some(fix) = &mut d.fix {
            for edit in &mut fix.edits {
                shift(&mut edit.span);
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use essl::diagnostic::Fix;
    use essl::diagnostic_code::Code;

    #[test]
    fn every_span_moves() {
        let mut d = [
            Diagnostic::error(Code::MissingSemicolon, "m", Span::new(3, 4))
                .with_secondary(Span::new(0, 1), "here")
                .with_fix(Fix::certain("insert `;`", Span::new(4, 4), ";")),
        ];
        relocate(&mut d, 10);
        assert_eq!(d[0].span, Span::new(13, 14));
        assert_eq!(d[0].secondary[0].span, Span::new(10, 11));
        assert_eq!(d[0].fix.as_ref().unwrap().edits[0].span, Span::new(14, 14));
    }
}
