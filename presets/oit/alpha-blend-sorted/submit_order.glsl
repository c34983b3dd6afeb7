// The application's object list: slot s of the submission holds object submitted_object(s), a
// permutation of 0..31 chosen by params.shuffle (0: identity). Sorted blending must give the same
// picture for every shuffle; the unsorted draw (params.sorted = false) shows the list's order.
// Multiplying by 5 (odd) is a bijection modulo 32 = OIT_INSTANCES.
int submitted_object(int slot) {
    return params.shuffle == 0 ? slot : (slot * 5 + params.shuffle * 7) % OIT_INSTANCES;
}
