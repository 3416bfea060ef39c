use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use thermobear::Bearing;

fn hertz(c: &mut Criterion) {
    let b = Bearing::preset("6208").unwrap();
    c.bench_function("hertz_exact_inner_contact", |bch| {
        bch.iter(|| b.inner_contact(black_box(0.26)).unwrap())
    });
}

criterion_group!(benches, hertz);
criterion_main!(benches);
