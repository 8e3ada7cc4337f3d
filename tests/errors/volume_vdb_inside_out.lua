-- A level set positive inside and negative outside (its background -0.001): said, not meshed inside out
volume.vdb("inside_out.vdb")
