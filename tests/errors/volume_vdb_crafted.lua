-- a 448-byte .vdb whose metadata declares a huge string (found by fuzzing): refused at once, no 10 s wait
volume.vdb("crafted_string.vdb")
