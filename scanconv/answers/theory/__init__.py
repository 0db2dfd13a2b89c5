"""The theory answers: the derivations with an input's numbers and the pseudocode of each
variant (`derivations`), the notes' errata in words (`errata`) and the theory topics
(`topics`: `scanconv theory`)."""
