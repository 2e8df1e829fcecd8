"""placeholder"""
def belt_drive(variant):
    return ""
